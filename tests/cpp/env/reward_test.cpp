#include <catch2/catch.hpp>

#include <cmath>

#include "core/common/error.h"
#include "core/env/reward.h"
#include "core/geometry/axis_cut.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {
Ring u_shape() { return {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}; }
}  // namespace

TEST_CASE("Eq. (1) by hand: the L-shape cut into two rectangles", "[env][reward]") {
  // Face size 2, so areas scale by 1/4. Pieces: 2x1 (A = 0.5, R = 2) and 1x1 (A = 0.25, R = 1).
  // aspect term  sqrt(N / sum R^2) = sqrt(2 / 5)                          = 0.6324555320
  // area term    mean A = 0.375; sum (A - mean)^2 = 2 * 0.125^2 = 0.03125; sum A = 0.75
  //              sqrt(0.03125 / 0.75)                                      = 0.2041241452
  // reward       3 (0.6324555320 - 0.2041241452) + 10 * 2/2 - 5 * 0 - 1   = 10.2849941604
  const GridFace face = test::grid_face_of(test::l_shape());
  const auto pieces = cut_part(face.whole, AxisLine{CutDirection::Horizontal, 1});
  CHECK(paper_reward(pieces, face.size) == Approx(10.2849941604).epsilon(1e-10));
}

TEST_CASE("Eq. (1) by hand: a cut that changes nothing", "[env][reward]") {
  // N = 1, the L itself: R = 1 (2x2 box), no area spread, N_q = 0, p(N) = 1:
  // 3 (sqrt(1 / 1) - 0) + 0 - 5 - 1 = -3
  const GridFace face = test::grid_face_of(test::l_shape());
  CHECK(paper_reward({face.whole}, face.size) == Approx(-3.0));
}

TEST_CASE("Eq. (1) by hand: the U-shape cut into three rectangles", "[env][reward]") {
  // Face size 3, areas scale by 1/9: 3x1 (A = 3/9, R = 3), two 1x1 (A = 1/9, R = 1).
  // aspect term  sqrt(3 / (9 + 1 + 1)) = sqrt(3/11)                          = 0.5222329679
  // area term    mean = 5/27; deviations 4/27, -2/27, -2/27; sum sq = 24/729; sum A = 5/9
  //              sqrt((24/729) / (5/9)) = sqrt(0.0592592593)                 = 0.2434322478
  // reward       3 (0.5222329679 - 0.2434322478) + 10 * 3/3 - 1              = 9.8364021603
  const GridFace face = test::grid_face_of(u_shape());
  const auto pieces = cut_part(face.whole, AxisLine{CutDirection::Horizontal, 1});
  REQUIRE(pieces.size() == 3);
  CHECK(paper_reward(pieces, face.size) == Approx(9.8364021603).epsilon(1e-10));
}

TEST_CASE("Eq. (1) does not depend on the drawing's units or position", "[env][reward]") {
  Ring scaled;
  for (const Point2& p : u_shape()) scaled.push_back({p.x * 25.4 - 1000.0, p.y * 25.4 + 0.5});
  const GridFace face = test::grid_face_of(scaled);
  const auto pieces = cut_part(face.whole, AxisLine{CutDirection::Horizontal, 1});
  CHECK(paper_reward(pieces, face.size) == Approx(9.8364021603).epsilon(1e-9));
}

TEST_CASE("the mesh preset by hand", "[env][reward]") {
  // L cut into 2x1 (R 2) and 1x1 (R 1): -(2 - 1) - 0.5 (ln 2 + ln 1) = -1.3465735903
  const GridFace l = test::grid_face_of(test::l_shape());
  CHECK(mesh_reward(cut_part(l.whole, AxisLine{CutDirection::Horizontal, 1})) == Approx(-1.3465735903));
  // A cut that changes nothing: -3.
  CHECK(mesh_reward({l.whole}) == Approx(-3.0));
  // U cut into 3x1 (R 3) and two 1x1: -(3 - 1) - 0.5 ln 3 = -2.5493061443
  const GridFace u = test::grid_face_of(u_shape());
  CHECK(cut_reward(RewardPreset::Mesh, cut_part(u.whole, AxisLine{CutDirection::Horizontal, 1}), u.size) ==
        Approx(-2.5493061443));
  CHECK(reward_preset_by_name("mesh") == RewardPreset::Mesh);
  CHECK(reward_preset_name(RewardPreset::Paper) == "paper");
  CHECK_THROWS_AS(reward_preset_by_name("fast"), InputError);
}
