// autoblock_bench_policies: how trained policies compare with the baselines, per data set:
// mean return under Eq. (1) and as a fraction of the optimal mean, blocks against the minimum
// partition, mean block aspect ratio, completion rate and decomposition time per face.
//
//   build/bin/autoblock_bench_policies --policy sac-paper --policy sac-mesh
//       --data models/data/test --generated 200 --large 100 --seed 4242     (one command line)
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <random>

#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/geometry/occt_face.h"
#include "core/io/dataset.h"
#include "core/io/input_face.h"
#include "core/sac/compute_threads.h"
#include "core/sac/lookahead_agent.h"
#include "core/api/policy_source.h"
#include "core/sac/policy_file.h"

using namespace autoblock;

namespace {

struct Figures {
  double paper_return = 0, mesh_return = 0, blocks = 0, min_blocks = 0, aspect = 0, complete = 0, capped = 0;
  std::vector<double> ms;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The return the same cuts earn under another reward preset.
double rescore(const GridFace& face, const std::vector<CutRecord>& cuts, RewardPreset preset) {
  EpisodeOptions options;
  options.reward = preset;
  options.max_steps = static_cast<int>(cuts.size()) + 1;
  Episode episode(face, options);
  for (const CutRecord& cut : cuts) {
    const int vertex = episode.vertex_at(cut.vertex);
    episode.step(Action{vertex, cut.direction});
  }
  return episode.total_return();
}

// Runs one policy over the faces with Eq. (1) and rescores its cuts with the mesh preset (optimal
// maximises the objective it is given).
Figures measure(const std::vector<GridFace>& faces, const std::string& name, RewardPreset objective) {
  BaselineOptions baseline;
  baseline.optimal_seconds = 60;
  baseline.reward = objective;
  // NAME@V: the learned policy NAME deployed with V symmetric views (lookahead agent).
  const size_t at = name.rfind('@');
  const PolicySource source(at == std::string::npos ? name : name.substr(0, at), baseline);
  std::shared_ptr<LookaheadAgent> agent;  // NAME@V: a copy of the policy loaded here, with V views
  if (at != std::string::npos) {
    if (source.path().empty()) throw InputError(name + ": views apply to learned policies only");
    agent = std::dynamic_pointer_cast<LookaheadAgent>(load_policy_file(source.path(), false).agent);
    if (!agent) throw InputError(name + ": views apply to the lookahead agent's policies only");
    agent->set_deploy_views(std::stoi(name.substr(at + 1)));
  }
  Figures f;
  for (size_t k = 0; k < faces.size(); ++k) {
    EpisodeOptions options;
    options.reward = RewardPreset::Paper;
    auto policy = agent ? agent->deployed_policy(name) : source.make(faces[k].size, k);
    const Decomposition d = decompose_face(faces[k], *policy, options);
    f.paper_return += d.total_return;
    f.blocks += static_cast<double>(d.blocks.size());
    f.min_blocks += d.min_blocks;
    f.complete += d.complete();
    f.capped += d.time_capped;
    f.ms.push_back(1e3 * d.seconds);
    double aspect = 0;
    for (const Box& b : d.blocks) aspect += b.aspect_ratio();
    f.aspect += aspect / static_cast<double>(std::max<size_t>(1, d.blocks.size()));
    f.mesh_return += rescore(faces[k], d.cuts, RewardPreset::Mesh);
  }
  const double n = static_cast<double>(faces.size());
  f.paper_return /= n;
  f.mesh_return /= n;
  f.blocks /= n;
  f.min_blocks /= n;
  f.aspect /= n;
  f.complete /= n;
  return f;
}

void table(const std::string& title, const std::vector<GridFace>& faces, const std::vector<std::string>& policies) {
  const Figures best = measure(faces, "optimal", RewardPreset::Paper);
  const Figures best_mesh = measure(faces, "optimal", RewardPreset::Mesh);
  std::printf("\n### %s (%zu faces)\n\n", title.c_str(), faces.size());
  std::printf("| policy | return (Eq. 1) | / optimal | mesh-preset return | blocks | minimum | blocks / minimum | mean aspect | complete | median ms / face |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  auto row = [&](const std::string& label, const Figures& f) {
    std::printf("| %s | %.3f | %.3f | %.3f | %.2f | %.2f | %.3f | %.3f | %.0f %% | %.2f |\n", label.c_str(), f.paper_return,
                f.paper_return / best.paper_return, f.mesh_return, f.blocks, f.min_blocks, f.blocks / f.min_blocks,
                f.aspect, 100 * f.complete, median(f.ms));
  };
  for (const std::string& p : policies) row(p, measure(faces, p, RewardPreset::Paper));
  row("optimal (Eq. 1)", best);
  row("optimal (mesh preset)", best_mesh);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Compare trained policies with the baselines."};
  std::vector<std::string> learned;
  std::string data = "models/data/test";
  int generated = 200, large = 100;
  std::uint64_t seed = 4242;
  app.add_option("--policy", learned, "trained policies (names or files; NAME@V: deployed with V symmetric views), repeatable");
  app.add_option("--data", data, "shipped test folder")->capture_default_str();
  app.add_option("--generated", generated, "fresh 2-10 rectangle faces")->capture_default_str();
  app.add_option("--large", large, "fresh 11-40 rectangle faces")->capture_default_str();
  app.add_option("--seed", seed, "generator seed")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    set_compute_threads(1);
    std::vector<std::string> policies = learned;
    for (const char* b : {"greedy", "random", "random-split"}) policies.push_back(b);
    std::vector<GridFace> shipped;
    for (const std::string& file : collect_shape_files({data})) shipped.push_back(load_input_face(file).grid);
    auto fresh = [seed](int count, int lo, int hi, std::uint64_t offset) {
      std::mt19937_64 rng(seed + offset);
      GeneratorOptions options;
      options.min_rects = lo;
      options.max_rects = hi;
      std::vector<GridFace> faces;
      for (int k = 0; k < count; ++k) faces.push_back(make_grid_face(generate_shape(rng, options).polygon));
      return faces;
    };
    table(data, shipped, policies);
    if (generated > 0) table("fresh 2-10 rectangles, seed " + std::to_string(seed), fresh(generated, 2, 10, 0), policies);
    if (large > 0) table("fresh 11-40 rectangles, seed " + std::to_string(seed + 1), fresh(large, 11, 40, 1), policies);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
