// autoblock_bench: time per cut and per episode of every baseline (and of replaying the cuts with
// OpenCASCADE) on the shipped test set and on freshly generated shapes. Prints a Markdown table.
//
//   build/src/bench/autoblock_bench --data models/data/test --generated 200 --seed 99
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <random>

#include "core/baselines/baseline_policy.h"
#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/env/occt_replay.h"
#include "core/geometry/occt_face.h"
#include "core/io/dataset.h"
#include "core/io/input_face.h"

using namespace autoblock;

namespace {

struct Row {
  double mean_episode_ms, median_episode_ms, cut_us, mean_return, mean_blocks, mean_min_blocks;
  int complete, shapes;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Runs the policy over every face `repeats` times and keeps each face's fastest time.
Row measure(const std::vector<InputFace>& faces, const std::string& policy_name, int repeats, bool occt_replay) {
  std::vector<double> episode_seconds;
  double total_seconds = 0, total_return = 0, total_blocks = 0, total_min = 0;
  long total_cuts = 0;
  int complete = 0;
  for (size_t k = 0; k < faces.size(); ++k) {
    double best = 1e30;
    Decomposition d;
    for (int r = 0; r < repeats; ++r) {
      BaselineOptions options;
      options.seed = k;
      options.optimal_seconds = 0;
      auto policy = make_baseline_policy(policy_name, faces[k].grid.size, options);
      d = decompose_face(faces[k].grid, *policy);
      double seconds = d.seconds;
      if (occt_replay) {
        const auto start = std::chrono::steady_clock::now();
        replay_cuts_occt(faces[k].occt, faces[k].grid, d.cuts);
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }
      best = std::min(best, seconds);
    }
    episode_seconds.push_back(best);
    total_seconds += best;
    total_cuts += static_cast<long>(d.cuts.size());
    total_return += d.total_return;
    total_blocks += static_cast<double>(d.blocks.size());
    total_min += d.min_blocks;
    complete += d.complete();
  }
  const double n = static_cast<double>(faces.size());
  return Row{1e3 * total_seconds / n, 1e3 * median(episode_seconds), 1e6 * total_seconds / std::max(1L, total_cuts),
             total_return / n, total_blocks / n, total_min / n, complete, static_cast<int>(faces.size())};
}

void print_table(const std::string& title, const std::vector<InputFace>& faces, int repeats) {
  std::printf("\n### %s (%zu shapes)\n\n", title.c_str(), faces.size());
  std::printf("| policy | mean ms / episode | median ms / episode | us / cut | mean return | mean blocks | mean minimum | complete |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& name : baseline_names()) {
    const Row r = measure(faces, name, repeats, false);
    std::printf("| %s | %.3f | %.3f | %.1f | %.3f | %.2f | %.2f | %d/%d |\n", name.c_str(), r.mean_episode_ms,
                r.median_episode_ms, r.cut_us, r.mean_return, r.mean_blocks, r.mean_min_blocks, r.complete, r.shapes);
  }
  const Row replay = measure(faces, "optimal", 1, true);
  std::printf("| optimal's cuts replayed by OpenCASCADE (BRepAlgoAPI_Splitter) | %.3f | %.3f | %.1f | | | | |\n",
              replay.mean_episode_ms, replay.median_episode_ms, replay.cut_us);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Time the baselines per cut and per episode."};
  std::string data = "models/data/test";
  int generated = 200, repeats = 3, min_rects = 2, max_rects = 10;
  std::uint64_t seed = 99;
  app.add_option("--data", data, "folder of shapes")->capture_default_str();
  app.add_option("--generated", generated, "number of freshly generated shapes")->capture_default_str();
  app.add_option("--min-rects", min_rects, "generated shapes: fewest rectangles")->capture_default_str();
  app.add_option("--max-rects", max_rects, "generated shapes: most rectangles")->capture_default_str();
  app.add_option("--seed", seed, "generator seed")->capture_default_str();
  app.add_option("--repeats", repeats, "runs per shape (the fastest counts)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    std::vector<InputFace> shipped;
    for (const std::string& file : collect_shape_files({data})) shipped.push_back(load_input_face(file));
    std::mt19937_64 rng(seed);
    GeneratorOptions options;
    options.min_rects = min_rects;
    options.max_rects = max_rects;
    std::vector<InputFace> fresh;
    for (int k = 0; k < generated; ++k) {
      const GeneratedShape shape = generate_shape(rng, options);
      fresh.push_back(input_face_from_occt(occt_face_from_polygon(shape.polygon, 0, true), "generated"));
    }
    print_table(data, shipped, repeats);
    print_table("generated, " + std::to_string(min_rects) + "-" + std::to_string(max_rects) + " rectangles, seed " +
                    std::to_string(seed),
                fresh, repeats);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
