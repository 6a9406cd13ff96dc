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

}  // namespace

TEST_CASE("search on general faces finishes them, never below greedy, and memoises parts", "[region][search]") {
  std::mt19937_64 rng(11);
  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  for (int i = 0; i < 6; ++i) {
    const Region face = generated_face(rng, i, 5, 7, 3);
    RegionGreedyPolicy greedy;
    RegionSearchOptions unlimited;
    unlimited.time_limit = 0.0;
    RegionSearchPolicy search(unlimited);
    const RegionDecomposition g = decompose_region(face, greedy, mesh);
    const RegionDecomposition s = decompose_region(face, search, mesh);
    REQUIRE(s.complete());
    CHECK_FALSE(s.time_capped);
    CHECK(s.total_return >= g.total_return - 1e-9);
    if (!s.cuts.empty()) CHECK(search.solved_parts() >= 1);
  }
}

TEST_CASE("search out of time finishes greedily: with no budget left it is the greedy policy", "[region][search]") {
  std::mt19937_64 rng(12);
  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  for (int i = 0; i < 4; ++i) {
    const Region face = generated_face(rng, i, 6, 9, 4);
    RegionGreedyPolicy greedy;
    RegionSearchOptions spent;
    spent.time_limit = 1e-9;  // the deadline has passed by the first choice
    RegionSearchPolicy search(spent);
    const RegionDecomposition g = decompose_region(face, greedy, mesh);
    const RegionDecomposition s = decompose_region(face, search, mesh);
    REQUIRE(s.complete());
    if (s.cuts.empty()) continue;
    CHECK(s.time_capped);
    REQUIRE(s.cuts.size() == g.cuts.size());
    CHECK(s.total_return == Approx(g.total_return));
    CHECK(s.blocks == g.blocks);
    CHECK(s.templates == g.templates);
  }
}
