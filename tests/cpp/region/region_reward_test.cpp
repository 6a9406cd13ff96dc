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

TEST_CASE("the mesh preset charges a template for the corners it makes and the obtuse ones it keeps", "[region][reward]") {
  constexpr double kQ = 1e-7;
  // A square's template: four quads with right angles at the feet and the centre, nothing to charge
  // beyond the template's own cost.
  const Region square(Ring{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {}, kQ);
  CHECK(region_template_reward(RewardPreset::Mesh, square, 2.0) == Approx(-3.0 - kTemplatePenalty));
  // A quadrilateral with a 155-degree corner: its quad there keeps the whole 155 degrees (sine 0.42),
  // which a block may not have under rules whose largest corner is 129 degrees, and its centre corner
  // is small: charged under both rules, more when the obtuse corner counts.
  const double t = 155.0 * M_PI / 180.0;
  const Region kite(Ring{{0, 0}, {4, 0}, {4 + 2 * std::cos(M_PI - t), 2 * std::sin(M_PI - t)}, {0, 3}}, {}, kQ);
  BlockRules loose, strict;
  loose.max_corner_degrees = 170.0;
  strict.max_corner_degrees = 129.0;
  const double with_loose = region_template_reward(RewardPreset::Mesh, kite, 4.0, loose);
  const double with_strict = region_template_reward(RewardPreset::Mesh, kite, 4.0, strict);
  CHECK(with_loose < -3.0 - kTemplatePenalty);
  CHECK(with_strict <= with_loose);
  // The paper preset (Eq. 1) ignores the rules' angles.
  CHECK(region_template_reward(RewardPreset::Paper, kite, 4.0, loose) == Approx(region_template_reward(RewardPreset::Paper, kite, 4.0, strict)));
}
