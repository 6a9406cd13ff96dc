// Transfinite interpolation and quad quality measures.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/mesh/mesh_quality.h"
#include "core/mesh/transfinite.h"

using namespace autoblock;

namespace {
std::vector<Point2> chain(Point2 a, Point2 b, const std::vector<double>& t) {
  std::vector<Point2> out;
  for (double s : t) out.push_back(Point2{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)});
  out.front() = a;
  out.back() = b;
  return out;
}
}  // namespace

TEST_CASE("transfinite interpolation of a rectangle gives exact rectangles", "[mesh][tfi]") {
  // Uneven but matching node positions on opposite sides, awkward decimals.
  const std::vector<double> xs{0.1, 0.37, 0.5 + 1.0 / 3.0, 1.9}, ys{-0.7, -0.1, 0.3};
  const std::vector<Point2> bottom{{xs[0], ys[0]}, {xs[1], ys[0]}, {xs[2], ys[0]}, {xs[3], ys[0]}};
  const std::vector<Point2> top{{xs[0], ys[2]}, {xs[1], ys[2]}, {xs[2], ys[2]}, {xs[3], ys[2]}};
  const std::vector<Point2> left{{xs[0], ys[0]}, {xs[0], ys[1]}, {xs[0], ys[2]}};
  const std::vector<Point2> right{{xs[3], ys[0]}, {xs[3], ys[1]}, {xs[3], ys[2]}};
  const std::vector<Point2> grid = transfinite_grid(bottom, top, left, right);
  REQUIRE(grid.size() == 12);
  for (size_t j = 0; j < 3; ++j) {
    for (size_t i = 0; i < 4; ++i) {
      CHECK(grid[j * 4 + i].x == xs[i]);  // bitwise
      CHECK(grid[j * 4 + i].y == ys[j]);
    }
  }
  for (size_t j = 0; j < 2; ++j) {
    for (size_t i = 0; i < 3; ++i) {
      const QuadQuality q = quad_quality({grid[j * 4 + i], grid[j * 4 + i + 1], grid[j * 4 + i + 5], grid[j * 4 + i + 4]});
      CHECK(q.scaled_jacobian == 1.0);
      CHECK(q.skew == 0.0);
      CHECK(q.min_angle == Approx(90.0));
      CHECK(q.max_angle == Approx(90.0));
    }
  }
}

TEST_CASE("transfinite interpolation reproduces an affine map and keeps curved sides", "[mesh][tfi]") {
  // A parallelogram with uniform sides: TFI is the affine map.
  const Point2 p00{0, 0}, p10{4, 1}, p01{1, 3}, p11{5, 4};
  const std::vector<double> u{0, 0.25, 0.5, 0.75, 1}, v{0, 1.0 / 3, 2.0 / 3, 1};
  const auto grid = transfinite_grid(chain(p00, p10, u), chain(p01, p11, u), chain(p00, p01, v), chain(p10, p11, v));
  for (size_t j = 0; j < v.size(); ++j) {
    for (size_t i = 0; i < u.size(); ++i) {
      CHECK(grid[j * u.size() + i].x == Approx(u[i] * 4 + v[j] * 1).margin(1e-12));
      CHECK(grid[j * u.size() + i].y == Approx(u[i] * 1 + v[j] * 3).margin(1e-12));
    }
  }
  // A bulging bottom side: boundary nodes are kept, the interior follows smoothly.
  std::vector<Point2> bottom = chain({0, 0}, {4, 0}, u);
  bottom[2].y = -1;
  const auto bulged = transfinite_grid(bottom, chain({0, 4}, {4, 4}, u), chain({0, 0}, {0, 4}, u), chain({4, 0}, {4, 4}, u));
  CHECK(bulged[2].y == -1);
  CHECK(bulged[5 * 2 + 2].y == Approx(2 - 0.5).margin(1e-12));  // (1 - v) of the bulge at v = 1/2
  CHECK_THROWS_AS(transfinite_grid(bottom, chain({0, 4}, {4, 4}, v), chain({0, 0}, {0, 4}, u), chain({4, 0}, {4, 4}, u)),
                  std::invalid_argument);
}

TEST_CASE("quad quality measures", "[mesh][quality]") {
  const QuadQuality rect = quad_quality({Point2{0, 0}, Point2{4, 0}, Point2{4, 1}, Point2{0, 1}});
  CHECK(rect.scaled_jacobian == 1.0);
  CHECK(rect.aspect_ratio == 4.0);
  CHECK(rect.skew == 0.0);
  const QuadQuality rhombus = quad_quality({Point2{0, 0}, Point2{2, 0}, Point2{3, std::sqrt(3.0)}, Point2{1, std::sqrt(3.0)}});
  CHECK(rhombus.scaled_jacobian == Approx(std::sin(M_PI / 3)));
  CHECK(rhombus.min_angle == Approx(60));
  CHECK(rhombus.max_angle == Approx(120));
  CHECK(rhombus.aspect_ratio == Approx(1));
  CHECK(rhombus.skew == Approx(0.5));  // |cos 60 degrees| between the principal axes
  const QuadQuality inverted = quad_quality({Point2{0, 0}, Point2{0, 1}, Point2{1, 1}, Point2{1, 0}});
  CHECK(inverted.scaled_jacobian == -1.0);
  const QuadQuality arrow = quad_quality({Point2{0, 0}, Point2{2, 1}, Point2{0, 2}, Point2{1, 1}});  // reflex corner
  CHECK(arrow.scaled_jacobian < 0);
  CHECK(arrow.max_angle > 180);
}

TEST_CASE("transfinite interpolation along the sides' lengths: the discrete sum where spacings agree",
          "[mesh][tfi][arc]") {
  // Where opposite sides space their nodes alike (here: a parallelogram, uniform or graded), the
  // grid lines run straight between matching nodes and both forms give the same grid.
  const Point2 p00{0, 0}, p10{4, 1}, p01{1, 3}, p11{5, 4};
  for (const std::vector<double>& u : {std::vector<double>{0, 0.25, 0.5, 0.75, 1}, std::vector<double>{0, 0.1, 0.3, 0.6, 1}}) {
    const std::vector<double> v{0, 0.2, 0.7, 1};
    const auto a = transfinite_grid(chain(p00, p10, u), chain(p01, p11, u), chain(p00, p01, v), chain(p10, p11, v));
    const auto b = transfinite_grid_by_length(chain(p00, p10, u), chain(p01, p11, u), chain(p00, p01, v), chain(p10, p11, v));
    REQUIRE(a.size() == b.size());
    for (size_t k = 0; k < a.size(); ++k) {
      CHECK(b[k].x == Approx(a[k].x).margin(1e-12));
      CHECK(b[k].y == Approx(a[k].y).margin(1e-12));
    }
  }
  // Opposite sides spaced differently (bottom graded to the left, top to the right): every interior
  // node lies on the straight grid line from its bottom node to its top node, and inside the block.
  const std::vector<double> left_graded{0, 0.05, 0.15, 0.35, 1}, right_graded{0, 0.65, 0.85, 0.95, 1}, v{0, 0.5, 1};
  const auto grid = transfinite_grid_by_length(chain({0, 0}, {4, 0}, left_graded), chain({0, 2}, {4, 2}, right_graded),
                                               chain({0, 0}, {0, 2}, v), chain({4, 0}, {4, 2}, v));
  for (size_t i = 1; i + 1 < left_graded.size(); ++i) {
    const Point2 p = grid[5 + i];
    CHECK(p.y == Approx(1.0));
    CHECK(p.x == Approx(0.5 * (4 * left_graded[i] + 4 * right_graded[i])));
  }
}
