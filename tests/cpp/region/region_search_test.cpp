#include "core/region/region_search.h"

#include <random>

#include <catch2/catch.hpp>

#include "core/data/general_generator.h"
#include "core/geometry/tolerance.h"

using namespace autoblock;

TEST_CASE("search on general faces finishes them, never below greedy, and memoises parts", "[region][search]") {
  std::mt19937_64 rng(11);
  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  for (int i = 0; i < 6; ++i) {
    GeneralOptions options;
    options.kind = i % 2 == 0 ? GeneralKind::Polygon : GeneralKind::Chamfered;
    options.min_vertices = 5;
    options.max_vertices = 7;
    options.max_rects = 3;
    const GeneralShape shape = generate_general_shape(rng, options);
    const Region face(shape.outer, shape.holes, tolerance_for_size(ring_bbox(shape.outer).longer_side()));
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
