#include "core/region/block.h"

#include <cmath>

#include <catch2/catch.hpp>

using namespace autoblock;

namespace {
constexpr double kQ = 1e-7;
}

TEST_CASE("blocks: four corners within the angle range, side vertices allowed", "[region][block]") {
  CHECK(is_block(Region(Ring{{0, 0}, {3, 0}, {3, 1}, {0, 1}}, {}, kQ)));
  // A side vertex at (1.5, 0.05) bends the bottom side by about 4 degrees: still four corners.
  const Region bent(Ring{{0, 0}, {1.5, 0.05}, {3, 0}, {3, 1}, {0, 1}}, {}, kQ);
  const auto corners = block_corners(bent);
  REQUIRE(corners);
  CHECK((*corners)[0] == 0);
  CHECK((*corners)[1] == 2);
  // A parallelogram at 60 degrees is a block; at 20 degrees it is not (default range 30-150).
  CHECK(is_block(Region(Ring{{0, 0}, {4, 0}, {5, std::sqrt(3.0)}, {1, std::sqrt(3.0)}}, {}, kQ)));
  const double t = 20.0 * M_PI / 180.0;
  const Region sharp(Ring{{0, 0}, {4, 0}, {4 + std::cos(t), std::sin(t)}, {std::cos(t), std::sin(t)}}, {}, kQ);
  CHECK_FALSE(is_block(sharp));
  BlockRules loose;
  loose.min_corner_degrees = 15.0;
  loose.max_corner_degrees = 165.0;
  loose.flat_tolerance_degrees = 10.0;
  CHECK(is_block(sharp, loose));
  // Triangles, pentagons, L-shapes and holed squares are not blocks.
  CHECK_FALSE(is_block(Region(Ring{{0, 0}, {1, 0}, {0, 1}}, {}, kQ)));
  CHECK_FALSE(is_block(Region(Ring{{0, 0}, {2, 0}, {2, 1}, {1, 2}, {0, 1}}, {}, kQ)));
  CHECK_FALSE(is_block(Region(Ring{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}, kQ)));
  CHECK_FALSE(is_block(Region(Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {Ring{{1, 1}, {2, 1}, {2, 2}, {1, 2}}}, kQ)));
}

TEST_CASE("the midpoint template: n quadrilaterals that tile the convex part", "[region][block]") {
  const Region triangle(Ring{{0, 0}, {6, 0}, {0, 6}}, {}, kQ);
  REQUIRE(template_applies(triangle));
  const auto quads = template_quads(triangle);
  REQUIRE(quads.size() == 3);
  double area = 0.0;
  for (const auto& q : quads) {
    double a = 0.0;
    for (size_t i = 0; i < 4; ++i) a += q[i].x * q[(i + 1) % 4].y - q[(i + 1) % 4].x * q[i].y;
    CHECK(a > 0.0);  // counter-clockwise, not inverted
    area += 0.5 * a;
  }
  CHECK(area == Approx(18.0));
  CHECK_FALSE(template_applies(Region(Ring{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}, kQ)));
}

TEST_CASE("the minimum-area rectangle: a turned rectangle is found in its own frame", "[region][block]") {
  const Region axis(Ring{{0, 0}, {4, 0}, {4, 1}, {0, 1}}, {}, kQ);
  const OrientedRectangle r = min_area_rectangle(axis);
  CHECK(r.axis.x == Approx(1.0));
  CHECK(r.aspect_ratio() == Approx(4.0));
  for (double degrees : {10.0, 33.0, 45.0, 71.0, 120.0}) {
    const double t = degrees * M_PI / 180.0, c = std::cos(t), s = std::sin(t);
    Ring turned;
    for (const Point2& p : axis.outer()) turned.push_back({c * p.x - s * p.y, s * p.x + c * p.y});
    const OrientedRectangle m = min_area_rectangle(Region(turned, {}, kQ));
    CHECK(m.aspect_ratio() == Approx(4.0));
    CHECK(m.width * m.height == Approx(4.0));
  }
}
