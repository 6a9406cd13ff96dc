// autoblock_bench_policies: how trained policies compare with the baselines, per data set:
// mean return under Eq. (1) and as a fraction of the optimal mean, blocks against the minimum
// partition, mean block aspect ratio, completion rate and decomposition time per face; and for each
// learned policy where its time goes (graphs, lookahead, network, the rest) and the graphs' sizes.
//
//   build/bin/autoblock_bench_policies --policy sac-paper --policy sac-mesh
//       --data models/data/test --generated 200 --large 100 --seed 4242     (one command line)
//
// --kind thin draws the fresh faces on a bounded grid so that features one unit wide are common
// (2-10 rectangles: 32 x 32 grid, sides 3-18; 11-40: 64 x 64, sides 4-24); --holes N adds N faces
// of 11-40 rectangles with holes of the same kind; --kind both measures both kinds.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <random>

#include "bench/bench_stats.h"
#include "core/common/error.h"
#include "core/data/thin_features.h"
#include "core/env/decomposition.h"
#include "core/geometry/occt_face.h"
#include "core/io/dataset.h"
#include "core/io/input_face.h"
#include "core/sac/compute_threads.h"
#include "core/sac/deploy_profile.h"
#include "core/sac/lookahead_agent.h"
#include "core/api/policy_source.h"
#include "core/sac/policy_file.h"

using namespace autoblock;

namespace {

struct Figures {
  double paper_return = 0, mesh_return = 0, blocks = 0, min_blocks = 0, aspect = 0, complete = 0, capped = 0;
  std::vector<double> ms;
  std::vector<double> cpu_ms;  // the thread's CPU time per face (the machine may be shared)
  DeployProfile profile;  // learned policies: summed over the faces
};

bool reuse_values = true;  // --no-reuse turns it off

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

using bench::quantile;

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
  // NAME[@V][#K]: the learned policy NAME deployed with V symmetric views and the network valuing
  // the pieces of the K best cuts by the two-step score (0: every cut; lookahead agent).
  const size_t hash = name.rfind('#');
  const std::string viewed = hash == std::string::npos ? name : name.substr(0, hash);
  const size_t at = viewed.rfind('@');
  const PolicySource source(at == std::string::npos ? viewed : viewed.substr(0, at), baseline);
  // A learned policy is loaded here (not through the source) so that its deployment can be set:
  // NAME@V, NAME#K (above), --no-reuse without reuse (lookahead agent).
  std::shared_ptr<LearningAgent> agent;
  const bool deployment_set = at != std::string::npos || hash != std::string::npos;
  if (!source.path().empty()) {
    agent = load_policy_file(source.path(), false).agent;
    auto lookahead = std::dynamic_pointer_cast<LookaheadAgent>(agent);
    if (deployment_set && !lookahead) throw InputError(name + ": @V and #K apply to the lookahead agent's policies only");
    if (at != std::string::npos) lookahead->set_deploy_views(std::stoi(viewed.substr(at + 1)));
    if (hash != std::string::npos) lookahead->set_deploy_top_k(std::stoi(name.substr(hash + 1)));
    if (lookahead) lookahead->set_deploy_reuse(reuse_values);
  } else if (deployment_set) {
    throw InputError(name + ": @V and #K apply to learned policies only");
  }
  Figures f;
  for (size_t k = 0; k < faces.size(); ++k) {
    EpisodeOptions options;
    options.reward = RewardPreset::Paper;
    auto policy = agent ? agent->deployed_policy(name) : source.make(faces[k].size, k);
    DeployProfile& profile = deploy_profile();
    profile = {};
    const double cpu_start = thread_cpu_seconds();
    const Decomposition d = decompose_face(faces[k], *policy, options);
    f.cpu_ms.push_back(1e3 * (thread_cpu_seconds() - cpu_start));
    f.profile.graph_seconds += profile.graph_seconds;
    f.profile.lookahead_seconds += profile.lookahead_seconds;
    f.profile.forward_seconds += profile.forward_seconds;
    f.profile.states += profile.states;
    f.profile.forwards += profile.forwards;
    f.profile.graphs_evaluated += profile.graphs_evaluated;
    f.profile.values_reused += profile.values_reused;
    f.profile.graph_nodes.insert(f.profile.graph_nodes.end(), profile.graph_nodes.begin(), profile.graph_nodes.end());
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

// Where a learned policy's decomposition time goes, per face (means), and the graphs' sizes.
void profile_table(const std::vector<std::pair<std::string, Figures>>& learned) {
  if (learned.empty()) return;
  std::printf("\nWhere the time goes (learned policies; wall ms per face, mean over the faces unless stated; CPU ms: "
              "the thread's CPU time):\n\n");
  std::printf("| policy | median ms | 90 %% ms | max ms | faces > 0.5 s CPU | CPU ms median (90 %%, max) | graphs | lookahead | network | rest | "
              "states / face | batches / face | graphs evaluated / face | values reused / face | nodes median (90 %%, max) |\n");
  std::printf("|---|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
  for (const auto& [name, f] : learned) {
    const double n = static_cast<double>(f.ms.size());
    double total = 0;
    int slow = 0;
    for (double ms : f.ms) total += ms;
    for (double ms : f.cpu_ms) slow += ms > 500.0;
    const DeployProfile& p = f.profile;
    const double graph = 1e3 * p.graph_seconds / n, look = 1e3 * p.lookahead_seconds / n, net = 1e3 * p.forward_seconds / n;
    const std::vector<double> nodes(p.graph_nodes.begin(), p.graph_nodes.end());
    std::printf("| %s | %.2f | %.2f | %.2f | %d | %.2f (%.2f, %.2f) | %.2f | %.2f | %.2f | %.2f | %.1f | %.1f | %.1f | %.1f | %.0f (%.0f, %.0f) |\n",
                name.c_str(), median(f.ms), quantile(f.ms, 0.9), quantile(f.ms, 1.0), slow, median(f.cpu_ms),
                quantile(f.cpu_ms, 0.9), quantile(f.cpu_ms, 1.0), graph, look, net,
                total / n - graph - look - net, static_cast<double>(p.states) / n, static_cast<double>(p.forwards) / n,
                static_cast<double>(p.graphs_evaluated) / n, static_cast<double>(p.values_reused) / n,
                quantile(nodes, 0.5), quantile(nodes, 0.9), quantile(nodes, 1.0));
  }
}

void table(const std::string& title, const std::vector<GridFace>& faces, const std::vector<std::string>& policies,
           size_t learned_count) {
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
  std::vector<std::pair<std::string, Figures>> learned;
  for (size_t k = 0; k < policies.size(); ++k) {
    Figures f = measure(faces, policies[k], RewardPreset::Paper);
    row(policies[k], f);
    if (k < learned_count) learned.emplace_back(policies[k], std::move(f));
  }
  row("optimal (Eq. 1)", best);
  row("optimal (mesh preset)", best_mesh);
  profile_table(learned);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Compare trained policies with the baselines."};
  std::vector<std::string> learned;
  std::string data = "models/data/test";
  int generated = 200, large = 100, holes = 0;
  std::uint64_t seed = 4242;
  std::string kind = "default";
  app.add_option("--policy", learned,
                 "trained policies (names or files; NAME@V: deployed with V symmetric views; NAME#K: the network "
                 "values the pieces of the K best cuts by the two-step score, 0: all), repeatable");
  app.add_option("--data", data, "shipped test folder (empty: none)")->capture_default_str();
  app.add_option("--generated", generated, "fresh 2-10 rectangle faces")->capture_default_str();
  app.add_option("--large", large, "fresh 11-40 rectangle faces")->capture_default_str();
  app.add_option("--holes", holes, "fresh 11-40 rectangle faces with holes")->capture_default_str();
  app.add_option("--seed", seed, "generator seed (2-10: seed, 11-40: seed + 1, holes: seed + 2; thin kind: + 10)")
      ->capture_default_str();
  app.add_flag_function("--no-reuse", [](std::int64_t) { reuse_values = false; },
               "learned policies value every step's pieces afresh (as before issue 8)");
  app.add_option("--kind", kind, "fresh faces: default (today's generator), thin (bounded grid, thin features), both")
      ->check(CLI::IsMember({"default", "thin", "both"}))
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    set_compute_threads(1);
    std::vector<std::string> policies = learned;
    for (const char* b : {"greedy", "random", "random-split"}) policies.push_back(b);
    std::vector<GridFace> shipped;
    if (!data.empty()) {
      for (const std::string& file : collect_shape_files({data})) shipped.push_back(load_input_face(file).grid);
    }
    // A fresh set: count faces of lo-hi rectangles; thin: on a bounded grid (see the top).
    auto fresh = [&](int count, int lo, int hi, bool with_holes, bool thin, std::uint64_t offset) {
      const std::uint64_t set_seed = seed + offset + (thin ? 10 : 0);
      std::mt19937_64 rng(set_seed);
      const GeneratorOptions options = generator_kind_options(thin, lo, hi, with_holes);
      std::vector<GridFace> faces;
      for (int k = 0; k < count; ++k) faces.push_back(make_grid_face(generate_shape(rng, options).polygon));
      std::string title = "fresh " + std::to_string(lo) + "-" + std::to_string(hi) + " rectangles" +
                          (with_holes ? " with holes" : "");
      if (thin) {
        title += ", thin features (grid " + std::to_string(options.grid) + ", sides " + std::to_string(options.min_side) +
                 "-" + std::to_string(options.max_side) + ")";
      }
      table(title + ", seed " + std::to_string(set_seed), faces, policies, learned.size());
    };
    if (!data.empty()) table(data, shipped, policies, learned.size());
    for (bool thin : {false, true}) {
      if (thin ? kind == "default" : kind == "thin") continue;
      if (generated > 0) fresh(generated, 2, 10, false, thin, 0);
      if (large > 0) fresh(large, 11, 40, false, thin, 1);
      if (holes > 0) fresh(holes, 11, 40, true, thin, 2);
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
