#include "core/region/region.h"

#include <cmath>

#include <catch2/catch.hpp>

using autoblock::Point2;
using autoblock::Region;
using autoblock::Ring;

namespace {
constexpr double kQ = 1e-7;
}

TEST_CASE("a region is canonical: orientation, start vertex, collinear and duplicate vertices", "[region]") {
  // Clockwise square starting at (1, 1), with a collinear vertex and a repeated one.
  const Ring cw{{1, 1}, {1, 0.5}, {1, 0}, {1, 0}, {0, 0}, {0, 1}};
  const Region region(cw, {}, kQ);
  REQUIRE(region.outer().size() == 4);
  CHECK(region.outer()[0] == Point2{0, 0});
  CHECK(region.outer()[1] == Point2{1, 0});
  CHECK(region.outer()[2] == Point2{1, 1});
  CHECK(region.area() == Approx(1.0));
  CHECK(region.centroid().x == Approx(0.5));
  CHECK(region.is_convex());

  // The same square drawn counter-clockwise from another corner is the same value, same hash.
  const Region same(Ring{{1, 0}, {1, 1}, {0, 1}, {0, 0}}, {}, kQ);
  CHECK(same == region);
  CHECK(same.hash() == region.hash());
  // Coordinates within half a quantum snap to the same lattice point.
  const Region nearly(Ring{{0, 0}, {1 + 0.3 * kQ, 0}, {1, 1}, {0, 1 - 0.2 * kQ}}, {}, kQ);
  CHECK(nearly == region);
  const Region other(Ring{{0, 0}, {2, 0}, {2, 1}, {0, 1}}, {}, kQ);
  CHECK_FALSE(other == region);
}

TEST_CASE("a region's holes run clockwise, sorted, and count in its area and centroid", "[region]") {
  const Ring outer{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Ring hole_a{{6, 6}, {8, 6}, {8, 8}, {6, 8}};  // counter-clockwise on input
  const Ring hole_b{{2, 2}, {2, 4}, {4, 4}, {4, 2}};
  const Region region(outer, {hole_a, hole_b}, kQ);
  REQUIRE(region.holes().size() == 2);
  CHECK(region.holes()[0][0] == Point2{2, 2});
  CHECK(autoblock::signed_area(region.holes()[0]) < 0.0);
  CHECK(autoblock::signed_area(region.holes()[1]) < 0.0);
  CHECK(region.area() == Approx(92.0));
  CHECK(region.centroid().x == Approx(5.0));
  CHECK(region.centroid().y == Approx(5.0));
  CHECK_FALSE(region.is_convex());
  CHECK(region.vertex_count() == 12);
  // The order of the holes on input does not matter.
  CHECK(Region(outer, {hole_b, hole_a}, kQ) == region);
}

TEST_CASE("canonical rings drop spikes and collapsed loops", "[region]") {
  // A zero-width spike from (1, 0) out to (3, 0) and back.
  const Ring spiky{{0, 0}, {1, 0}, {3, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Region region(spiky, {}, kQ);
  CHECK(region.outer().size() == 4);
  CHECK(region.area() == Approx(1.0));
  CHECK(autoblock::canonical_ring(Ring{{0, 0}, {1, 1}, {2, 2}}, kQ).empty());
  CHECK(Region(Ring{{0, 0}, {1, 0}, {1, 0.5 * kQ}}, {}, kQ).is_empty());
}

TEST_CASE("interior angles of a ring with the region on its left", "[region]") {
  // An L: the corner at (1, 1) is re-entrant.
  const Ring l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  CHECK(autoblock::interior_angle(l, 0) == Approx(M_PI / 2));
  CHECK(autoblock::interior_angle(l, 3) == Approx(3 * M_PI / 2));
  const Ring triangle{{0, 0}, {1, 0}, {0, 1}};
  CHECK(autoblock::interior_angle(triangle, 1) == Approx(M_PI / 4));
}
