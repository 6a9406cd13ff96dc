#include "core/region/region_reward.h"

#include <cmath>
#include <memory>

#include <catch2/catch.hpp>

#include "core/geometry/axis_cut.h"
#include "core/geometry/part.h"

using namespace autoblock;

TEST_CASE("Eq. (1) on regions equals the grid engine's on rectilinear pieces", "[region][reward]") {
  // An L of three unit cells, cut along y = 1: a 2 x 1 rectangle below and a 1 x 1 square above.
  auto grid = std::make_shared<Grid>();
  grid->xs = {0, 1, 2};
  grid->ys = {0, 1, 2};
  const Part l(grid, {{0, 0}, {1, 0}, {0, 1}});
  const std::vector<Part> parts = cut_part(l, AxisLine{CutDirection::Horizontal, 1});
  REQUIRE(parts.size() == 2);
  const Region region_l(Ring{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}, 1e-7);
  const CutOutcome outcome = cut_region(region_l, {CutKind::Partial, {1, 1}, {-1, 0}});
  REQUIRE(outcome.pieces.size() == 2);
  CHECK(region_cut_reward(RewardPreset::Paper, outcome, 2.0) == Approx(paper_reward(parts, 2.0)));
  // A cut that changes nothing: N = 1 in both engines.
  const CutOutcome nothing = cut_region(region_l, {CutKind::Full, {0, 0}, {1, 0}});
  CHECK(region_cut_reward(RewardPreset::Paper, nothing, 2.0) == Approx(paper_reward({l}, 2.0)));
  CHECK(region_cut_reward(RewardPreset::Mesh, nothing, 2.0) == Approx(mesh_reward({l})));
  // The mesh preset: two rectangles meeting the cut at right angles cost the grid's price.
  CHECK(region_cut_reward(RewardPreset::Mesh, outcome, 2.0) == Approx(mesh_reward(parts)));
}

TEST_CASE("the mesh preset charges the sharp corners a cut creates", "[region][reward]") {
  const Region square(Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}, 1e-7);
  // From the corner (0, 0): along the diagonal (new corners of 45 degrees) or towards (4, 1) (a new
  // corner of 14 degrees).
  const double diagonal = region_cut_reward(RewardPreset::Mesh, cut_region(square, {CutKind::Partial, {0, 0}, {1, 1}}), 4.0);
  const double sharp = region_cut_reward(RewardPreset::Mesh, cut_region(square, {CutKind::Partial, {0, 0}, {4, 1}}), 4.0);
  CHECK(diagonal == Approx(-1.0 - kMeshShapeWeight * (1.0 - std::sqrt(0.5))));
  CHECK(diagonal > sharp);
  // Finishing a triangle with the template costs more than one cut.
  const Region triangle(Ring{{0, 0}, {4, 0}, {0, 4}}, {}, 1e-7);
  CHECK(region_template_reward(RewardPreset::Mesh, triangle, 4.0) < -1.0);
}
