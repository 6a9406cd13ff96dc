#include "core/region/region_search.h"

#include <random>

#include <catch2/catch.hpp>

#include "core/data/general_generator.h"
#include "core/geometry/tolerance.h"
#include "core/region/region_reward.h"

using namespace autoblock;

namespace {

// A generated polygon (even i) or chamfered union (odd i) of min_vertices..max_vertices as a region.
Region generated_face(std::mt19937_64& rng, int i, int min_vertices, int max_vertices, int max_rects) {
  GeneralOptions options;
  options.kind = i % 2 == 0 ? GeneralKind::Polygon : GeneralKind::Chamfered;
  options.min_vertices = min_vertices;
  options.max_vertices = max_vertices;
  options.max_rects = max_rects;
  const GeneralShape shape = generate_general_shape(rng, options);
  return Region(shape.outer, shape.holes, tolerance_for_size(ring_bbox(shape.outer).longer_side()));
}

// The face decomposed with the mesh preset by greedy and by the search with the given time limit
// (without the taper charge: the search ranks candidates by reward, as greedy does).
struct GreedyAndSearch {
  RegionDecomposition greedy, search;
  size_t solved_parts = 0;  // the search's memo after the run
};
GreedyAndSearch greedy_and_search(const Region& face, double time_limit) {
  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  RegionGreedyPolicy greedy;
  RegionSearchOptions options;
  options.time_limit = time_limit;
  options.taper = false;
  RegionSearchPolicy search(options);
  GreedyAndSearch result{decompose_region(face, greedy, mesh), decompose_region(face, search, mesh)};
  result.solved_parts = search.solved_parts();
  return result;
}

// What the search maximises under the mesh preset: the return less its finished blocks' taper costs.
double taper_cost(const RegionDecomposition& d) {
  double cost = 0.0;
  for (const FinishedRegion& f : d.finished) {
    if (!f.is_template) cost += block_taper_cost(f.region, f.corners);
  }
  return cost;
}
double search_objective(const RegionDecomposition& d) { return d.total_return - taper_cost(d); }

// The two decompositions made the same actions, in the same order.
void check_same_cuts(const RegionDecomposition& a, const RegionDecomposition& b) {
  REQUIRE(a.cuts.size() == b.cuts.size());
  for (size_t k = 0; k < a.cuts.size(); ++k) {
    CHECK(a.cuts[k].action.kind == b.cuts[k].action.kind);
    CHECK(a.cuts[k].action.cut.origin == b.cuts[k].action.cut.origin);
    CHECK(a.cuts[k].action.cut.direction == b.cuts[k].action.cut.direction);
  }
}

}  // namespace

TEST_CASE("search on general faces finishes them, never below greedy, and memoises parts", "[region][search]") {
  std::mt19937_64 rng(11);
  for (int i = 0; i < 6; ++i) {
    const Region face = generated_face(rng, i, 5, 7, 3);
    const auto [g, s, solved_parts] = greedy_and_search(face, 0.0);  // no time limit
    REQUIRE(s.complete());
    CHECK_FALSE(s.time_capped);
    CHECK(s.total_return >= g.total_return - 1e-9);
    if (!s.cuts.empty()) CHECK(solved_parts >= 1);
  }
}

TEST_CASE("search charges the blocks it leaves for their taper, and trades return for it", "[region][search]") {
  // The search with the charge (the default) and without, on the same polygons: with it the blocks
  // taper less, for some return, and what it maximises (the return less the charge) is higher.
  std::mt19937_64 rng(14);
  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  double cost_tapered = 0.0, cost_plain = 0.0, objective_tapered = 0.0, objective_plain = 0.0;
  int traded = 0;
  for (int i = 0; i < 16; ++i) {
    const Region face = generated_face(rng, 2 * i, 8, 14, 5);  // polygons
    RegionSearchOptions options;
    options.time_limit = 0.0;
    RegionSearchPolicy tapered(options);
    options.taper = false;
    RegionSearchPolicy plain(options);
    const RegionDecomposition t = decompose_region(face, tapered, mesh), p = decompose_region(face, plain, mesh);
    REQUIRE(t.complete());
    REQUIRE(p.complete());
    cost_tapered += taper_cost(t);
    cost_plain += taper_cost(p);
    objective_tapered += search_objective(t);
    objective_plain += search_objective(p);
    traded += taper_cost(t) < taper_cost(p) - 1e-9 && t.total_return < p.total_return;
  }
  CHECK(cost_tapered < cost_plain);
  CHECK(objective_tapered > objective_plain);
  CHECK(traded > 0);
}

TEST_CASE("search out of time finishes greedily: with no budget left it is the greedy policy", "[region][search]") {
  std::mt19937_64 rng(12);
  for (int i = 0; i < 4; ++i) {
    const Region face = generated_face(rng, i, 6, 9, 4);
    const auto [g, s, solved_parts] = greedy_and_search(face, 1e-9);  // the deadline has passed by the first choice
    REQUIRE(s.complete());
    if (s.cuts.empty()) continue;
    CHECK(s.time_capped);
    REQUIRE(s.cuts.size() == g.cuts.size());
    CHECK(s.total_return == Approx(g.total_return));
    CHECK(s.blocks == g.blocks);
    CHECK(s.templates == g.templates);
  }
}

TEST_CASE("search: branch and bound prunes candidates and decides as the search without it", "[region][search]") {
  std::mt19937_64 rng(13);
  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  size_t pruned = 0;
  for (int i = 0; i < 8; ++i) {
    const Region face = generated_face(rng, i, 8, 14, 5);
    RegionSearchOptions options;
    options.time_limit = 0.0;  // no limit: both searches see every candidate they expand
    RegionSearchPolicy bounded(options);
    options.prune = false;
    RegionSearchPolicy exhaustive(options);
    const RegionDecomposition a = decompose_region(face, bounded, mesh), b = decompose_region(face, exhaustive, mesh);
    REQUIRE(a.complete());
    CHECK(a.total_return == b.total_return);
    check_same_cuts(a, b);
    CHECK(bounded.solved_parts() <= exhaustive.solved_parts());
    CHECK(exhaustive.pruned_candidates() == 0);
    pruned += bounded.pruned_candidates();
  }
  CHECK(pruned > 0);
  // Eq. (1) can be positive: no bound but the values of pieces already solved; the same decisions.
  RegionEpisodeOptions paper;
  paper.reward = RewardPreset::Paper;
  const Region face = generated_face(rng, 0, 8, 12, 4);
  RegionSearchOptions options;
  options.time_limit = 0.0;
  RegionSearchPolicy bounded(options);
  options.prune = false;
  RegionSearchPolicy exhaustive(options);
  CHECK(decompose_region(face, bounded, paper).total_return == decompose_region(face, exhaustive, paper).total_return);
}

TEST_CASE("search: its budget is counted in work, so a capped search repeats exactly", "[region][search]") {
  std::mt19937_64 rng(17);
  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  int capped = 0;
  for (int i = 0; i < 4; ++i) {
    const Region face = generated_face(rng, i, 16, 24, 6);
    RegionSearchOptions options;
    options.time_limit = 0.0;
    RegionSearchPolicy unlimited(options);
    const RegionDecomposition whole = decompose_region(face, unlimited, mesh);
    REQUIRE(whole.complete());
    CHECK_FALSE(whole.time_capped);
    CHECK(whole.work > 0);
    // A third of that work as the budget: the search is capped there, whatever the machine's speed.
    options.time_limit = 0.3 * static_cast<double>(whole.work) / kSearchWorkPerSecond;
    std::vector<RegionDecomposition> runs;
    for (int k = 0; k < 3; ++k) {
      RegionSearchPolicy search(options);
      runs.push_back(decompose_region(face, search, mesh));
    }
    REQUIRE(runs[0].complete());
    if (!runs[0].time_capped) continue;
    ++capped;
    CHECK(runs[0].work > std::llround(0.3 * static_cast<double>(whole.work)) - 1);
    for (int k = 1; k < 3; ++k) {
      CHECK(runs[k].time_capped);
      CHECK(runs[k].work == runs[0].work);
      CHECK(runs[k].total_return == runs[0].total_return);
      check_same_cuts(runs[k], runs[0]);
    }
  }
  CHECK(capped >= 2);
}
