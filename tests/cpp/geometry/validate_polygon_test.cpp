#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/common/error.h"
#include "core/geometry/validate_polygon.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;

namespace {
RectilinearPolygon validate(const Ring& outer, const std::vector<Ring>& holes = {}) {
  return test::polygon_of(outer, holes);
}
}  // namespace

TEST_CASE("validate_rings keeps corners and orients the outer ring counter-clockwise", "[geometry]") {
  Ring clockwise = test::l_shape();
  std::reverse(clockwise.begin(), clockwise.end());
  const RectilinearPolygon p = validate(clockwise);
  CHECK(p.outer.size() == 6);
  CHECK(signed_area(p.outer) == Approx(3.0));
  CHECK(p.holes.empty());
}

TEST_CASE("validate_rings orients holes clockwise and finds the outer ring by area", "[geometry]") {
  std::vector<RawRing> rings{{"wire 1", test::centre_hole()}, {"wire 2", test::square3()}};
  const RectilinearPolygon p = validate_rings(rings);
  CHECK(signed_area(p.outer) == Approx(9.0));
  REQUIRE(p.holes.size() == 1);
  CHECK(signed_area(p.holes[0]) == Approx(-1.0));
  CHECK(polygon_area(p) == Approx(8.0));
}

TEST_CASE("validate_rings merges collinear edges", "[geometry]") {
  const RectilinearPolygon p = validate({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}});
  CHECK(p.outer.size() == 4);
}

TEST_CASE("validate_rings snaps coordinates within the relative tolerance", "[geometry]") {
  // Size 2: tolerance 2e-7. A vertex 1e-9 off the axis line is on it.
  double tolerance = 0;
  const RectilinearPolygon p =
      validate_rings({{"outer wire", {{0, 0}, {2, 1e-9}, {2, 2}, {0, 2}}}}, &tolerance);
  CHECK(tolerance == Approx(2e-7));
  CHECK(p.outer.size() == 4);
  CHECK(p.outer[0].y == p.outer[1].y);
}

TEST_CASE("validate_rings accepts real coordinates at any scale and offset", "[geometry]") {
  for (double scale : {1e-3, 0.1, 1.0, 37.5, 1e6}) {
    Ring ring;
    for (const Point2& q : test::l_shape()) ring.push_back({q.x * scale + 0.1 * scale - 12.345, q.y * scale + 1e3});
    const RectilinearPolygon p = validate(ring);
    CHECK(p.outer.size() == 6);
    CHECK(polygon_area(p) == Approx(3.0 * scale * scale));
  }
}

TEST_CASE("validate_rings names the edge that is not axis-parallel", "[geometry][errors]") {
  REQUIRE_THROWS_WITH(validate({{0, 0}, {2, 0}, {3, 2}, {0, 2}}),
                      Contains("edge 2 of the outer wire, from (2, 0) to (3, 2), is not parallel to the X or Y axis"));
}

TEST_CASE("validate_rings rejects an edge shorter than the tolerance", "[geometry][errors]") {
  REQUIRE_THROWS_WITH(validate({{0, 0}, {2, 0}, {2, 0}, {2, 2}, {0, 2}}), Contains("shorter than the tolerance"));
}

TEST_CASE("validate_rings rejects a boundary that doubles back", "[geometry][errors]") {
  REQUIRE_THROWS_WITH(validate({{0, 0}, {4, 0}, {4, 2}, {4, 1}, {0, 1}}), Contains("doubles back on itself at (4, 2)"));
}

TEST_CASE("validate_rings rejects a boundary that touches itself", "[geometry][errors]") {
  REQUIRE_THROWS_WITH(validate({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 1}, {0, 1}}),
                      Contains("the outer wire touches itself at (1, 1)"));
}

TEST_CASE("validate_rings rejects a boundary that crosses itself", "[geometry][errors]") {
  REQUIRE_THROWS_WITH(validate({{0, 0}, {2, 0}, {2, 2}, {1, 2}, {1, -1}, {0, -1}}),
                      Contains("the outer wire crosses itself at (1, 0)"));
}

TEST_CASE("validate_rings rejects a hole touching the outer boundary", "[geometry][errors]") {
  REQUIRE_THROWS_WITH(validate(test::square3(), {{{0, 1}, {1, 1}, {1, 2}, {0, 2}}}),
                      Contains("the outer wire touches the inner wire 1 at (0, 1)"));
}

TEST_CASE("validate_rings rejects holes outside the face or inside another hole", "[geometry][errors]") {
  REQUIRE_THROWS_WITH(validate(test::square3(), {{{5, 5}, {6, 5}, {6, 6}, {5, 6}}}), Contains("lies outside the outer wire"));
  REQUIRE_THROWS_WITH(validate({{0, 0}, {9, 0}, {9, 9}, {0, 9}}, {{{1, 1}, {8, 1}, {8, 8}, {1, 8}}, {{{3, 3}, {4, 3}, {4, 4}, {3, 4}}}}),
                      Contains("lies inside the hole"));
}

TEST_CASE("validate_rings rejects zero, tiny and too small areas", "[geometry][errors]") {
  REQUIRE_THROWS_WITH(validate({{0, 0}, {1, 0}, {2, 0}, {3, 0}}), Contains("zero or tiny area"));
  REQUIRE_THROWS_WITH(validate({{0, 0}, {1, 0}, {1, 1e-12}, {0, 1e-12}}), Contains("zero or tiny area"));
  REQUIRE_THROWS_WITH(validate({{0, 0}, {1e-8, 0}, {1e-8, 1e-8}, {0, 1e-8}}), Contains("smallest supported size"));
}

TEST_CASE("validate_rings rejects coordinates that are not finite", "[geometry][errors]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_THROWS_AS(validate({{0, 0}, {1, 0}, {1, nan}, {0, 1}}), InputError);
}

TEST_CASE("validate_rings rejects coordinates so large that areas overflow", "[geometry][errors]") {
  // Found by tests/fuzz/fuzz_polygon: a face at the scale 1e300 was accepted with a NaN area.
  REQUIRE_THROWS_WITH(validate({{0, 0}, {1e300, 0}, {1e300, 1e300}, {0, 1e300}}), Contains("are not supported"));
  REQUIRE_THROWS_WITH(validate({{1e150, 0}, {1e150 + 1e140, 0}, {1e150 + 1e140, 1e140}, {1e150, 1e140}}),
                      Contains("are not supported"));
  CHECK(polygon_area(validate({{0, 0}, {1e99, 0}, {1e99, 1e99}, {0, 1e99}})) == Approx(1e198));
}
