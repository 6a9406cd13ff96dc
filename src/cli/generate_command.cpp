// autoblock generate --count N --seed S [--min-rects 2] [--max-rects 10] [--holes]
//                    [--grid 0] [--min-side 2] [--max-side 12] --out DIR
#include <iostream>
#include <random>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "core/common/format.h"
#include "core/data/shape_generator.h"
#include "core/io/dataset.h"

namespace autoblock::cli {

void add_generate_command(CLI::App& app) {
  struct Arguments {
    int count = 0;
    std::uint64_t seed = 0;
    GeneratorOptions options;
    std::string out;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "generate", "Write random connected unions of axis-aligned rectangles (.brep files plus index.json).");
  command->add_option("--count", args->count, "number of shapes")->required()->check(CLI::Range(1, 1000000));
  command->add_option("--seed", args->seed, "random seed (same seed, same shapes)")->required();
  command->add_option("--min-rects", args->options.min_rects, "fewest rectangles per shape")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command->add_option("--max-rects", args->options.max_rects, "most rectangles per shape")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command->add_option("--min-side", args->options.min_side, "shortest rectangle side (grid units)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  command->add_option("--max-side", args->options.max_side, "longest rectangle side (grid units)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  command->add_option("--grid", args->options.grid,
                      "keep every rectangle inside a GRID x GRID square (0: unbounded); with a small grid "
                      "and long sides, features one unit wide are common")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  command->add_flag("--holes", args->options.holes, "give every shape one or two holes");
  command->add_option("--out", args->out, "output folder (created when missing)")->required();
  command->callback([args] {
    std::mt19937_64 rng(args->seed);
    std::vector<GeneratedShape> shapes;
    for (int k = 0; k < args->count; ++k) shapes.push_back(generate_shape(rng, args->options));
    const nlohmann::json generator = {{"seed", args->seed},
                                      {"count", args->count},
                                      {"min_rects", args->options.min_rects},
                                      {"max_rects", args->options.max_rects},
                                      {"holes", args->options.holes},
                                      {"min_side", args->options.min_side},
                                      {"max_side", args->options.max_side},
                                      {"grid", args->options.grid}};
    write_dataset(args->out, shapes, generator);
    std::cout << "wrote " << counted(static_cast<long long>(shapes.size()), "shape") << " and index.json to " << args->out << "\n";
  });
}

}  // namespace autoblock::cli
