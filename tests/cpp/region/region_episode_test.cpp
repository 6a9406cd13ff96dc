#include "core/region/region_episode.h"

#include <cmath>

#include <catch2/catch.hpp>

#include "core/region/region_policy.h"
#include "core/region/region_search.h"
#include "core/region/region_snapshot.h"

using namespace autoblock;

namespace {

constexpr double kQ = 1e-6;

// A 10 x 6 rectangle with one corner chamfered: two 135-degree corners, bound sin 67.5.
Region chamfered() { return Region(Ring{{0, 0}, {10, 0}, {10, 4}, {8, 6}, {0, 6}}, {}, kQ); }

}  // namespace

TEST_CASE("the mesh preset's block rules come from the face's bound, the paper preset keeps the default", "[region][episode]") {
  const Region face = chamfered();
  const double bound = scaled_jacobian_bound(face.loops());
  REQUIRE(bound == Approx(std::sin(67.5 * M_PI / 180.0)));
  const BlockRules expected = mesh_block_rules(face.loops());
  CHECK(expected.min_corner_degrees == Approx(std::asin(kMeshCornerFraction * bound) * 180.0 / M_PI));
  CHECK(expected.min_corner_degrees + expected.max_corner_degrees == Approx(180.0));
  // The chamfer's 135-degree corners are no block corners under them (they must be split).
  CHECK(expected.max_corner_degrees < 135.0);

  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  CHECK(RegionEpisode(face, mesh).options().rules.min_corner_degrees == Approx(expected.min_corner_degrees));
  RegionEpisodeOptions paper;
  paper.reward = RewardPreset::Paper;
  CHECK(RegionEpisode(face, paper).options().rules.min_corner_degrees == Approx(BlockRules{}.min_corner_degrees));
  RegionEpisodeOptions given = mesh;
  given.face_rules = false;
  given.rules.min_corner_degrees = 10.0;
  CHECK(RegionEpisode(face, given).options().rules.min_corner_degrees == Approx(10.0));
  // A square trapezoid with one 135-degree corner is a block by default, not under the mesh rules.
  const Region trapezoid(Ring{{0, 0}, {4, 0}, {4, 2}, {2, 4}, {0, 4}}, {}, kQ);
  const Region piece(Ring{{0, 0}, {4, 0}, {4, 2}, {2, 4}}, {}, kQ);
  CHECK(is_block(piece));
  CHECK_FALSE(is_block(piece, mesh_block_rules(trapezoid.loops())));
}

TEST_CASE("a decomposition records its rules, and replaying its actions rebuilds the same parts", "[region][episode]") {
  const Region face = chamfered();
  RegionEpisodeOptions mesh;
  mesh.reward = RewardPreset::Mesh;
  RegionSearchOptions unlimited;
  unlimited.time_limit = 0.0;
  RegionSearchPolicy search(unlimited);
  const RegionDecomposition d = decompose_region(face, search, mesh);
  REQUIRE(d.complete());
  CHECK(d.rules.max_corner_degrees == Approx(mesh_block_rules(face.loops()).max_corner_degrees));
  // Every block's corners lie within the face's rules.
  for (const FinishedRegion& f : d.finished) {
    if (!f.is_template) CHECK(is_block(f.region, d.rules));
  }
  const RegionDecomposition again = replay_region_decomposition(face, region_action_specs(d.cuts), mesh, "replay");
  REQUIRE(again.finished.size() == d.finished.size());
  for (size_t i = 0; i < d.finished.size(); ++i) {
    CHECK(again.finished[i].region == d.finished[i].region);
    CHECK(again.finished[i].is_template == d.finished[i].is_template);
  }
}
