// The scaled Jacobian of a quad against hand values, and against the corner-by-corner definition.
#include "core/mesh/mesh_quality.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

using namespace autoblock;

namespace {

// The definition, corner by corner: the sine of the angle between the corner's two edges (negative
// where the corner turns the wrong way), the smallest of the four.
double by_definition(const std::array<Point2, 4>& p) {
  double worst = 1e300;
  for (size_t k = 0; k < 4; ++k) {
    const Point2 c = p[k], next = p[(k + 1) % 4], prev = p[(k + 3) % 4];
    const double ax = next.x - c.x, ay = next.y - c.y, bx = prev.x - c.x, by = prev.y - c.y;
    const double la = std::hypot(ax, ay), lb = std::hypot(bx, by);
    worst = std::min(worst, la > 0 && lb > 0 ? (ax * by - ay * bx) / (la * lb) : 0.0);
  }
  return worst;
}

}  // namespace

TEST_CASE("scaled Jacobian of quads by hand", "[mesh][quality]") {
  // A rectangle: every corner a right angle.
  CHECK(quad_scaled_jacobian({Point2{0, 0}, {3, 0}, {3, 1}, {0, 1}}) == Approx(1.0));
  // A rhombus of 60 and 120 degrees: sin 60 at every corner.
  const double h = std::sqrt(3.0) / 2.0;
  CHECK(quad_scaled_jacobian({Point2{0, 0}, {1, 0}, {1.5, h}, {0.5, h}}) == Approx(h));
  // A trapezoid with a 45-degree corner: sin 45.
  CHECK(quad_scaled_jacobian({Point2{0, 0}, {3, 0}, {2, 1}, {0, 1}}) == Approx(std::sqrt(0.5)));
  // Clockwise: every corner turns the wrong way, -1 for a square.
  CHECK(quad_scaled_jacobian({Point2{0, 0}, {0, 1}, {1, 1}, {1, 0}}) == Approx(-1.0));
  // A dart (one reflex corner of 270 degrees): sin 270 = -1 there.
  CHECK(quad_scaled_jacobian({Point2{0, 0}, {2, 0}, {2, 2}, {1.5, 0.5}}) < 0.0);
  // A repeated node (a collapsed edge): 0 at its corners.
  CHECK(quad_scaled_jacobian({Point2{0, 0}, {1, 0}, {1, 0}, {0, 1}}) == 0.0);
}

TEST_CASE("edge ratio of quads by hand", "[mesh][quality]") {
  CHECK(quad_edge_ratio({Point2{0, 0}, {3, 0}, {3, 1}, {0, 1}}) == Approx(3.0));
  CHECK(quad_edge_ratio({Point2{0, 0}, {1, 0}, {1.5, 1}, {0.5, 1}}) == Approx(std::sqrt(1.25)));
  // A quad drawn into a triangle (an edge of 1e-6): a good scaled Jacobian, an edge ratio of millions.
  const std::array<Point2, 4> sliver{Point2{0, 0}, {2, 0}, {2 + 0.5e-6, 1e-6 * std::sqrt(0.75)}, {1, std::sqrt(3.0)}};
  CHECK(quad_scaled_jacobian(sliver) > 0.8);
  CHECK(quad_edge_ratio(sliver) > 1e6);
  CHECK(quad_edge_ratio({Point2{0, 0}, {1, 0}, {1, 0}, {0, 1}}) == INFINITY);
  CHECK(quad_quality({Point2{0, 0}, {3, 0}, {3, 1}, {0, 1}}).aspect_ratio == quad_edge_ratio({Point2{0, 0}, {3, 0}, {3, 1}, {0, 1}}));
}

TEST_CASE("meshes are judged valid and undegenerate first, then by their minimum scaled Jacobian", "[mesh][quality]") {
  // Three meshes of one face: a sound one of 0.6; one of 0.9 whose worst quad is a sliver (an edge
  // ratio of millions); one with an inverted quad.
  auto mesh_of = [](std::vector<std::array<Point2, 4>> quads) {
    QuadMesh m;
    for (const auto& q : quads) {
      std::array<int, 4> ids{};
      for (size_t k = 0; k < 4; ++k) {
        ids[k] = static_cast<int>(m.nodes.size());
        m.nodes.push_back(q[k]);
      }
      m.quads.push_back(ids);
      m.quad_block.push_back(0);
    }
    m.blocks = 1;
    return mesh_quality(m);
  };
  const double s = std::sqrt(3.0);
  const MeshQuality sound = mesh_of({{Point2{0, 0}, {1, 0}, {1.8, 0.6}, {0.8, 0.6}}});
  const MeshQuality sliver = mesh_of({{Point2{0, 0}, {2, 0}, {2 + 0.5e-6, 1e-6 * std::sqrt(0.75)}, {1, s}}, {Point2{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  const MeshQuality inverted = mesh_of({{Point2{0, 0}, {2, 0}, {2, 2}, {1.5, 0.5}}});
  REQUIRE(sliver.min_scaled_jacobian > sound.min_scaled_jacobian);
  CHECK(sound.max_aspect_ratio <= kDegenerateEdgeRatio);
  CHECK(sliver.max_aspect_ratio > kDegenerateEdgeRatio);
  CHECK(judged_jacobian(sound) == sound.min_scaled_jacobian);
  CHECK(judged_jacobian(sliver) == Approx(sliver.min_scaled_jacobian - 1.0));
  CHECK(judged_jacobian(sound) > judged_jacobian(sliver));
  CHECK(judged_jacobian(sliver) > judged_jacobian(inverted));
  CHECK(judged_jacobian(inverted) == Approx(inverted.min_scaled_jacobian - 2.0));
}

TEST_CASE("scaled Jacobian: each edge's length once gives the corner-by-corner values", "[mesh][quality]") {
  std::mt19937 random(20261203);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  for (int trial = 0; trial < 2000; ++trial) {
    std::array<Point2, 4> p;
    for (Point2& q : p) q = Point2{coordinate(random), coordinate(random)};
    CHECK(quad_scaled_jacobian(p) == Approx(by_definition(p)).margin(1e-12));
  }
}
