#include "core/region/region_search.h"

#include <random>

#include <catch2/catch.hpp>

#include "core/data/general_generator.h"
#include "core/geometry/tolerance.h"

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

// The face decomposed with the mesh preset by greedy and by the search with the given time limit.
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
  RegionSearchPolicy search(options);
  GreedyAndSearch result{decompose_region(face, greedy, mesh), decompose_region(face, search, mesh)};
  result.solved_parts = search.solved_parts();
  return result;
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
