// Learned policies on general faces (issue 12) against the general engine's greedy and search.
//
// Fresh generated polygons (a quarter with holes) of 5-12 and 13-40 vertices, and faces with circular
// arcs (--arcs, their engine polygons: arcs as chords): each policy decomposes
// each face under the mesh preset (one thread; the search with its default width and 2 s budget),
// and its decomposition is meshed once at the default size (no tries: the decomposition's own
// quality; a decomposition the mesher refuses counts as not meshed, its quality 0). A learned policy is a lookahead agent's value network (a shipped name or a policy file)
// deployed by RegionLookaheadPolicy with the file's deploy_top_k (NAME#K: with K instead; NAME+taper: deployed with region_taper). --budget S
// adds the search with a time limit of S seconds per face (repeatable: quality against time budget).
// Reported per policy: mean minimum scaled Jacobian over the face's bound, mean blocks, median and
// mean decomposition time, and how many faces ran out of time (the search finishes those greedily).
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <random>

#include "bench/bench_stats.h"
#include "core/api/policy_source.h"
#include "core/data/arc_generator.h"
#include "core/data/general_generator.h"
#include "core/geometry/occt_face.h"
#include "core/io/input_face.h"
#include "core/mesh/mesh_pipeline.h"
#include "core/region/region_search.h"
#include "core/sac/compute_threads.h"
#include "core/sac/deploy_profile.h"
#include "core/sac/policy_file.h"
#include "core/sac/region_lookahead_policy.h"

using namespace autoblock;

namespace {

struct Row {
  Row(std::string name_, std::shared_ptr<LookaheadAgent> agent_ = nullptr, double time_limit_ = 2.0)
      : name(std::move(name_)), agent(std::move(agent_)), time_limit(time_limit_) {}
  std::string name;
  std::shared_ptr<LookaheadAgent> agent;  // null: a baseline
  double time_limit = 2.0;                // the search's budget per face
  std::vector<double> ratio, seconds, blocks;
  int unmeshed = 0;  // decompositions the mesher refused
  int capped = 0;    // decompositions that ran out of time
  long proposals = 0, proposals_progress = 0, proposals_chosen = 0;  // the actor's (cut_proposer.h)
};

std::unique_ptr<RegionPolicy> make_policy(const Row& row) {
  if (row.agent) return std::make_unique<RegionLookaheadPolicy>(row.agent, row.name);
  if (row.name == "greedy") return std::make_unique<RegionGreedyPolicy>();
  RegionSearchOptions options;
  options.time_limit = row.time_limit;
  return std::make_unique<RegionSearchPolicy>(options);
}

std::string per_face_csv;  // --per-face: every face's ratio, blocks and time per policy

void table(const std::string& title, const std::vector<InputFace>& faces, std::vector<Row> rows) {
  RegionEpisodeOptions episode;
  episode.reward = RewardPreset::Mesh;
  for (const InputFace& face : faces) {
    for (Row& row : rows) {
      std::unique_ptr<RegionPolicy> policy = make_policy(row);
      RegionDecomposition d;
      const DeployProfile before = deploy_profile();
      const auto start = std::chrono::steady_clock::now();
      {
        const auto lock = lock_general_engine();
        d = decompose_region(face.region, *policy, episode);
      }
      row.proposals += deploy_profile().proposals - before.proposals;
      row.proposals_progress += deploy_profile().proposals_progress - before.proposals_progress;
      row.proposals_chosen += deploy_profile().proposals_chosen - before.proposals_chosen;
      row.seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      if (policy->time_capped()) ++row.capped;
      MeshOptions options;
      options.general = episode;
      row.blocks.push_back(static_cast<double>(d.finished.size()));
      try {
        const MeshResult m = mesh_region_decomposition(face, d, options);
        row.ratio.push_back(m.quality.min_scaled_jacobian / m.bound);
      } catch (const std::exception&) {
        ++row.unmeshed;  // blocks that admit no interval counts, say: counted, its quality 0
        row.ratio.push_back(0.0);
      }
    }
  }
  if (!per_face_csv.empty()) {
    std::FILE* out = std::fopen(per_face_csv.c_str(), "a");
    if (!out) throw std::runtime_error("cannot write " + per_face_csv);
    for (size_t f = 0; f < faces.size(); ++f) {
      for (const Row& row : rows) {
        std::fprintf(out, "\"%s\",%zu,\"%s\",%.6f,%.0f,%.6f\n", title.c_str(), f, row.name.c_str(), row.ratio[f],
                     row.blocks[f], row.seconds[f]);
      }
    }
    std::fclose(out);
  }
  std::printf("\n### %s (%zu faces)\n\n", title.c_str(), faces.size());
  std::printf("| policy | meshed | mean min SJ / bound (0 if not meshed) | mean blocks | median ms | mean ms | out of time |\n"
              "|---|---:|---:|---:|---:|---:|---:|\n");
  for (const Row& row : rows) {
    auto mean = [](const std::vector<double>& v) {
      double s = 0.0;
      for (const double x : v) s += x;
      return v.empty() ? 0.0 : s / static_cast<double>(v.size());
    };
    std::printf("| %s | %zu/%zu | %.4f | %.2f | %.1f | %.1f | %d |\n", row.name.c_str(), row.ratio.size() - row.unmeshed,
                row.ratio.size(), mean(row.ratio), mean(row.blocks),
                1e3 * bench::quantile(row.seconds, 0.5), 1e3 * mean(row.seconds), row.capped);
  }
  for (const Row& row : rows) {
    if (row.proposals == 0) continue;
    std::printf("\n%s: the actor proposed %ld cuts, %ld made progress, %ld were taken\n", row.name.c_str(), row.proposals,
                row.proposals_progress, row.proposals_chosen);
  }
  std::fflush(stdout);
}

std::vector<InputFace> fresh_faces(int count, int min_vertices, int max_vertices, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<InputFace> faces;
  for (int k = 0; static_cast<int>(faces.size()) < count && k < 100 * count; ++k) {
    GeneralOptions options;
    options.kind = GeneralKind::Polygon;
    options.holes = k % 4 == 0;
    options.min_vertices = min_vertices;
    options.max_vertices = max_vertices;
    const GeneralShape shape = generate_general_shape(rng, options);
    InputFace face = input_face_from_occt(occt_face_from_polygon(RectilinearPolygon{shape.outer, shape.holes}, 0.0, true), "face");
    if (face.is_general()) faces.push_back(std::move(face));
  }
  return faces;
}

// count faces with circular arcs (the five kinds in turn, scales 0.1-100), seed.
std::vector<InputFace> arc_faces(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<InputFace> faces;
  ArcOptions options;
  for (int k = 0; k < count; ++k) {
    const ArcFace face = generate_arc_face(rng, options);
    faces.push_back(input_face_from_occt(face.face, face.name));
  }
  return faces;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Learned policies on general faces against greedy and search."};
  std::vector<std::string> learned{"sac-mesh"};
  int small = 200, large = 100, arcs = 0;
  std::uint64_t seed = 20261205;
  std::vector<double> budgets;
  app.add_option("--policy", learned, "lookahead policies (shipped names or files; NAME#K values the K best cuts; NAME+taper charges the search's taper), repeatable")
      ->capture_default_str();
  app.add_option("--budget", budgets, "also the search with this time limit per face, in seconds (repeatable)")
      ->check(CLI::PositiveNumber);
  app.add_option("--small", small, "fresh polygons of 5-12 vertices")->capture_default_str();
  app.add_option("--large", large, "fresh polygons of 13-40 vertices")->capture_default_str();
  app.add_option("--arcs", arcs, "fresh faces with circular arcs (fillets, holes, slots, rounded polygons)")
      ->capture_default_str();
  app.add_option("--per-face", per_face_csv, "append every face's figures to this CSV (set, face, policy, ratio, blocks, seconds)");
  app.add_option("--seed", seed, "generator seed (13-40: seed + 1, arcs: seed + 2)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    set_compute_threads(1);
    std::vector<Row> rows{Row("greedy"), Row("search")};
    for (const double budget : budgets) {
      char name[64];
      std::snprintf(name, sizeof name, "search, %g s", budget);
      rows.push_back(Row(name, nullptr, budget));
    }
    for (const std::string& spec : learned) {
      const bool taper = spec.size() > 6 && spec.compare(spec.size() - 6, 6, "+taper") == 0;
      const std::string base = taper ? spec.substr(0, spec.size() - 6) : spec;
      const size_t hash = base.rfind('#');
      const std::string name = hash == std::string::npos ? base : base.substr(0, hash);
      const std::string path =
          std::filesystem::exists(name) ? name : models_folder() + "/policies/" + name + ".pt";
      LoadedPolicy loaded = load_policy_file(path, false);
      auto agent = std::dynamic_pointer_cast<LookaheadAgent>(loaded.general_agent());
      if (!agent) throw std::runtime_error(name + " is not a lookahead agent's policy");
      if (hash != std::string::npos) agent->set_deploy_top_k(std::stoi(base.substr(hash + 1)));
      if (taper) agent->set_region_taper(true);
      rows.push_back(Row(spec, agent));
    }
    if (small > 0) table("polygons of 5-12 vertices, a quarter with holes, seed " + std::to_string(seed), fresh_faces(small, 5, 12, seed), rows);
    if (large > 0) {
      table("polygons of 13-40 vertices, a quarter with holes, seed " + std::to_string(seed + 1),
            fresh_faces(large, 13, 40, seed + 1), rows);
    }
    if (arcs > 0) table("faces with circular arcs, seed " + std::to_string(seed + 2), arc_faces(arcs, seed + 2), rows);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
