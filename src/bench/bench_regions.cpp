// The general engine on generated general faces (issue 10): per policy, how many faces end in blocks,
// the blocks and templates made, the corner quality of the finished parts against the face's bound,
// and the time per face. Not a test: figures are reported, never asserted.
//
// Corner quality of a decomposition: the smallest sine of a corner angle over its blocks, and the
// smallest scaled Jacobian of its templates' quadrilaterals: what a mapped mesh of those parts reaches
// at best at their corners. The face's bound: the minimum over its corners of angle t of the maximum
// over k >= 1 of sin(t / k) (issue 10's definition).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/bench_stats.h"
#include "core/data/general_generator.h"
#include "core/geometry/tolerance.h"
#include "core/mesh/mesh_quality.h"
#include "core/region/region_search.h"

namespace {

using namespace autoblock;

double face_bound(const Region& face) {
  double bound = 1.0;
  for (int k = 0; k < face.loop_count(); ++k) {
    const Ring& ring = face.loop(k);
    for (size_t i = 0; i < ring.size(); ++i) {
      const double t = interior_angle(ring, i);
      double best = 0.0;
      for (int m = 1; m <= 8; ++m) best = std::max(best, std::sin(t / m));
      bound = std::min(bound, best);
    }
  }
  return bound;
}

double corner_quality(const RegionDecomposition& d) {
  double q = 1.0;
  for (const FinishedRegion& f : d.finished) {
    if (f.is_template) {
      for (const auto& quad : template_quads(f.region)) q = std::min(q, quad_quality(quad).scaled_jacobian);
    } else {
      for (int c : f.corners) q = std::min(q, std::sin(interior_angle(f.region.outer(), static_cast<size_t>(c))));
    }
  }
  return q;
}

struct Row {
  int faces = 0, complete = 0, capped = 0, same = 0;
  std::vector<double> blocks, templates, ratio, seconds, returns;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The general engine's policies on generated general faces"};
  int count = 50, min_v = 5, max_v = 12, seed = 1;
  double time_limit = 2.0;
  std::string preset = "mesh";
  app.add_option("--count", count, "faces per kind");
  app.add_option("--min-vertices", min_v, "polygon faces: fewest vertices");
  app.add_option("--max-vertices", max_v, "polygon faces: most vertices");
  app.add_option("--seed", seed, "generator seed");
  app.add_option("--time-limit", time_limit, "search: seconds per face");
  app.add_option("--reward", preset, "paper or mesh");
  CLI11_PARSE(app, argc, argv);

  std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
  const GeneralKind kinds[] = {GeneralKind::Polygon, GeneralKind::Turned, GeneralKind::Chamfered};
  // "search, no pruning": the same search without its branch and bound (the same decisions when no
  // face reaches the time limit), for its time.
  std::vector<std::string> names{"greedy", "search", "search, no pruning"};
  std::vector<Row> rows(names.size());
  RegionEpisodeOptions options;
  options.reward = reward_preset_by_name(preset);
  for (int i = 0; i < 3 * count; ++i) {
    GeneralOptions g;
    g.kind = kinds[i % 3];
    g.min_vertices = min_v;
    g.max_vertices = max_v;
    g.max_rects = std::max(2, max_v / 2);
    g.holes = i % 4 == 0;
    const GeneralShape shape = generate_general_shape(rng, g);
    const Region face(shape.outer, shape.holes, tolerance_for_size(ring_bbox(shape.outer).longer_side()));
    const double bound = face_bound(face);
    for (size_t p = 0; p < names.size(); ++p) {
      std::unique_ptr<RegionPolicy> policy;
      if (names[p] == "greedy") {
        policy = std::make_unique<RegionGreedyPolicy>();
      } else {
        RegionSearchOptions so;
        so.time_limit = time_limit;
        so.prune = names[p] == "search";
        policy = std::make_unique<RegionSearchPolicy>(so);
      }
      const RegionDecomposition d = decompose_region(face, *policy, options);
      Row& row = rows[p];
      ++row.faces;
      row.complete += d.complete() ? 1 : 0;
      row.capped += d.time_capped ? 1 : 0;
      row.blocks.push_back(d.blocks);
      row.templates.push_back(d.templates);
      row.ratio.push_back(corner_quality(d) / bound);
      row.seconds.push_back(d.seconds);
      row.returns.push_back(d.total_return);
      if (p == 2 && d.total_return == rows[1].returns.back()) ++row.same;
    }
  }
  std::printf("%d faces (polygon %d-%d vertices, turned and chamfered unions; a quarter with holes), reward %s\n",
              3 * count, min_v, max_v, preset.c_str());
  std::printf("| policy | complete | mean blocks | mean templates | corner quality / bound: mean | min | median s | max s | time-capped |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (size_t p = 0; p < names.size(); ++p) {
    const Row& r = rows[p];
    double mb = 0, mt = 0, mr = 0, minr = 1e9;
    for (size_t k = 0; k < r.blocks.size(); ++k) {
      mb += r.blocks[k];
      mt += r.templates[k];
      mr += r.ratio[k];
      minr = std::min(minr, r.ratio[k]);
    }
    const double n = static_cast<double>(r.faces);
    std::printf("| %s | %d/%d | %.2f | %.2f | %.3f | %.3f | %.3f | %.3f | %d |\n", names[p].c_str(), r.complete, r.faces,
                mb / n, mt / n, mr / n, minr, bench::quantile(r.seconds, 0.5), bench::quantile(r.seconds, 1.0), r.capped);
  }
  std::printf("search without pruning: the same return as with it on %d of %d faces\n", rows[2].same, rows[2].faces);
  return 0;
}
