// autoblock generate --count N --seed S [--min-rects 2] [--max-rects 10] [--holes]
//                    [--grid 0] [--min-side 2] [--max-side 12] --out DIR
//                    [--kind rectangles|polygon|turned|chamfered|arcs] [--min-scale 0.1] [--max-scale 100]
#include <iostream>
#include <algorithm>
#include <random>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "core/common/error.h"
#include "core/common/format.h"
#include "core/data/arc_generator.h"
#include "core/data/shape_generator.h"
#include "core/io/dataset.h"

namespace autoblock::cli {

void add_generate_command(CLI::App& app) {
  struct Arguments {
    int count = 0;
    std::uint64_t seed = 0;
    GeneratorOptions options;
    GeneralOptions general;
    ArcOptions arcs;
    std::string kind = "rectangles";
    std::string out;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "generate", "Write random faces (.brep files plus index.json): unions of axis-aligned rectangles, or general faces (--kind).");
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
  command->add_option("--kind", args->kind,
                      "rectangles (unions of axis-aligned rectangles) | polygon (random simple polygons, edges at any "
                      "angle) | turned (unions turned by a random angle) | chamfered (unions with 45-degree chamfers) | arcs "
                      "(faces with circular arcs: filleted unions, plates with round holes or a slot, rounded polygons, "
                      "rounded plates with holes)")
      ->check(CLI::IsMember({"rectangles", "polygon", "turned", "chamfered", "arcs"}))
      ->capture_default_str();
  command->add_option("--min-vertices", args->general.min_vertices, "polygon: fewest vertices")
      ->check(CLI::Range(3, 100000))
      ->capture_default_str();
  command->add_option("--max-vertices", args->general.max_vertices, "polygon: most vertices")
      ->check(CLI::Range(3, 100000))
      ->capture_default_str();
  command->add_option("--min-scale", args->arcs.min_scale, "arcs: smallest scale (plates 6-24 by 4-14 times it, polygons of radius 10 times it)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--max-scale", args->arcs.max_scale, "arcs: largest scale (scales drawn log-uniformly)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--out", args->out, "output folder (created when missing)")->required();
  command->callback([args] {
    std::mt19937_64 rng(args->seed);
    if (args->kind == "arcs") {
      if (args->arcs.min_scale > args->arcs.max_scale) throw InputError("--min-scale is above --max-scale");
      std::vector<ArcFace> faces;
      for (int k = 0; k < args->count; ++k) faces.push_back(generate_arc_face(rng, args->arcs));
      const nlohmann::json generator = {{"seed", args->seed}, {"count", args->count}, {"kind", args->kind},
                                        {"min_scale", args->arcs.min_scale}, {"max_scale", args->arcs.max_scale}};
      write_arc_dataset(args->out, faces, generator);
      std::cout << "wrote " << counted(static_cast<long long>(faces.size()), "shape") << " and index.json to " << args->out << "\n";
      return;
    }
    if (args->kind != "rectangles") {
      GeneralOptions o = args->general;
      o.kind = general_kind_by_name(args->kind);
      o.min_rects = args->options.min_rects;
      o.max_rects = args->options.max_rects;
      o.holes = args->options.holes;
      if (o.min_vertices > o.max_vertices) throw InputError("--min-vertices is above --max-vertices");
      if (o.min_rects > o.max_rects) throw InputError("--min-rects is above --max-rects");
      std::vector<GeneralShape> shapes;
      for (int k = 0; k < args->count; ++k) shapes.push_back(generate_general_shape(rng, o));
      const nlohmann::json generator = {{"seed", args->seed}, {"count", args->count}, {"kind", args->kind},
                                        {"min_vertices", o.min_vertices}, {"max_vertices", o.max_vertices},
                                        {"min_rects", o.min_rects}, {"max_rects", o.max_rects}, {"holes", o.holes}};
      write_general_dataset(args->out, shapes, generator);
      std::cout << "wrote " << counted(static_cast<long long>(shapes.size()), "shape") << " and index.json to " << args->out << "\n";
      return;
    }
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
