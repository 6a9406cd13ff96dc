#include "core/region/region_reward.h"

#include <cmath>
#include <memory>
#include <random>

#include <catch2/catch.hpp>

#include "core/geometry/axis_cut.h"
#include "core/geometry/part.h"
#include "core/data/general_generator.h"
#include "core/geometry/tolerance.h"
#include "core/region/region_candidates.h"
#include "core/region/region_cut.h"
#include "support/test_shapes.h"

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

TEST_CASE("a block's taper, and what the search charges for it", "[region][reward]") {
  // Taper: the larger ratio of opposite sides' lengths, each side summed along the boundary.
  const Region rectangle(Ring{{0, 0}, {4, 0}, {4, 1}, {0, 1}}, {}, 1e-7);
  CHECK(block_taper(rectangle, {0, 1, 2, 3}) == Approx(1.0));
  CHECK(block_taper_cost(rectangle, {0, 1, 2, 3}) == 0.0);
  const Region trapezoid(Ring{{0, 0}, {6, 0}, {3.5, 1}, {2.5, 1}}, {}, 1e-7);
  CHECK(block_taper(trapezoid, {0, 1, 2, 3}) == Approx(6.0));
  CHECK(block_taper_cost(trapezoid, {0, 1, 2, 3}) == Approx(kMeshTaperWeight * std::log(6.0 / kMeshTaperFrom)));
  const Region bent(Ring{{0, 0}, {3, 0.01}, {6, 0}, {6, 1}, {0, 1}}, {}, 1e-7);
  CHECK(block_taper(bent, {0, 2, 3, 4}) == Approx(2.0 * std::hypot(3.0, 0.01) / 6.0));
  // Up to kMeshTaperFrom a taper is free: a trapezoid with parallel sides 6 and 2.
  const Region mild(Ring{{0, 0}, {6, 0}, {4, 1}, {2, 1}}, {}, 1e-7);
  CHECK(block_taper_cost(mild, {0, 1, 2, 3}) == 0.0);
  // Not part of the reward: a cut leaving a taper-7 block earns what it did without the term.
  const Region long_rectangle(Ring{{0, 0}, {8, 0}, {8, 2}, {0, 2}}, {}, 1e-7);
  const CutOutcome outcome = cut_region(long_rectangle, {CutKind::Full, {0.5, 0}, {3, 2}});
  REQUIRE(outcome.pieces.size() == 2);
  double thin = 0.0;
  for (const Region& piece : outcome.pieces) {
    REQUIRE(is_block(piece));
    thin += std::log(min_area_rectangle(piece).aspect_ratio());
  }
  const double expected = -1.0 - kMeshThinWeight * thin - kMeshShapeWeight * (1.0 - std::sin(std::atan2(2.0, 3.0)));
  CHECK(region_cut_reward(RewardPreset::Mesh, outcome, 8.0) == Approx(expected));
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

TEST_CASE("the bound of a cut's mesh reward from its chords is never below the reward (property test)", "[region][reward][property]") {
  // Every candidate cut (region_candidates) of generated faces and of the pieces their first cuts
  // leave, under the default rules and under a face's adapted ones: where the fast path tells the
  // chords, region_cut_reward_bound from them bounds region_cut_reward of the outcome from above.
  std::mt19937_64 rng(808);
  const GeneralKind kinds[] = {GeneralKind::Polygon, GeneralKind::Chamfered, GeneralKind::Turned};
  BlockRules adapted;
  adapted.min_corner_degrees = 50.0;
  adapted.max_corner_degrees = 130.0;
  long checked = 0, single = 0;
  for (int i = 0; i < 60; ++i) {
    GeneralOptions options;
    options.kind = kinds[i % 3];
    options.max_vertices = i % 4 == 0 ? 20 : 10;
    options.size = std::pow(10.0, static_cast<double>(i % 5) - 2.0);
    const GeneralShape shape = generate_general_shape(rng, options);
    const Region face(shape.outer, shape.holes, tolerance_for_size(ring_bbox(shape.outer).longer_side()));
    for (const Region& part : test::face_and_first_pieces(face, 6)) {
      if (!part.holes().empty()) continue;
      for (const BlockRules& rules : {BlockRules{}, adapted}) {
        for (const RegionAction& a : region_candidates(part)) {
          if (a.kind != RegionAction::Kind::Cut) continue;
          std::vector<Chord> chords;
          bool told = false;
          const std::optional<CutOutcome> o = cut_region_if(part, a.cut, [&](const std::vector<Chord>& c) {
            chords = c;
            told = true;
            return true;
          });
          if (!told || !o || o->pieces.size() < 2) continue;
          const double bound = region_cut_reward_bound(RewardPreset::Mesh, part, chords, rules);
          const double reward = region_cut_reward(RewardPreset::Mesh, *o, 1.0, rules);
          INFO("face " << i << ", cut from (" << a.cut.origin.x << ", " << a.cut.origin.y << ")");
          CHECK(reward <= bound + 1e-12);
          ++checked;
          if (chords.size() == 1 && std::isfinite(bound)) ++single;
        }
      }
    }
  }
  CHECK(checked > 5000);
  CHECK(single > 2000);  // the one-chord bound (the shape term) is exercised, not only the count
  // Eq. (1) can be positive: no bound.
  const Region square(Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {}, 1e-7);
  CHECK(std::isinf(region_cut_reward_bound(RewardPreset::Paper, square, {Chord{{0, 2}, {4, 2}}})));
}
