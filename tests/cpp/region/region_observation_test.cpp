#include "core/region/region_observation.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "core/geometry/part_boundary.h"
#include "core/geometry/tolerance.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("the observation at a triangle's corners, by hand", "[region][observation]") {
  // (0,0), (4,0), (0,3): s = 4, centroid (4/3, 1). At (0,0): previous (0,3), next (4,0), a right
  // angle. At (4,0): previous (0,0), next (0,3), the angle atan(3/4) = 36.87 degrees.
  const Region triangle(Ring{{0, 0}, {4, 0}, {0, 3}}, {}, 1e-9);
  REQUIRE(triangle.outer()[0] == Point2{0, 0});
  const Observation a = observe_region_vertex(triangle, 0, 0);
  const std::vector<double> expected_a{0, 0.75, 1, 0, 1.0 / 3, 0.25, 0.25, 1, 0.75};
  for (int k = 0; k < kObservationSize; ++k) CHECK(a[static_cast<size_t>(k)] == Approx(expected_a[static_cast<size_t>(k)]));
  const Observation b = observe_region_vertex(triangle, 0, 1);
  const double angle = std::atan2(3.0, 4.0) * 180.0 / 3.14159265358979323846;
  const std::vector<double> expected_b{-1, 0, -1, 0.75, -2.0 / 3, 0.25, angle / 360.0, 1, 0.75};
  for (int k = 0; k < kObservationSize; ++k) CHECK(b[static_cast<size_t>(k)] == Approx(expected_b[static_cast<size_t>(k)]));
  CHECK_THROWS_AS(observe_region_vertex(triangle, 1, 0), std::out_of_range);
  CHECK_THROWS_AS(observe_region_vertex(triangle, 0, 3), std::out_of_range);
}

TEST_CASE("the region observation on a rectilinear part is the grid's", "[region][observation]") {
  // Generated faces with holes: at every corner the 9 numbers of observe_vertex (the region's
  // vertices are on its lattice, within half a quantum of the grid's corners).
  GeneratorOptions options;
  options.holes = true;
  int compared = 0;
  for (const GeneratedShape& shape : test::generated_shapes(20, 41, options)) {
    const GridFace face = make_grid_face(shape.polygon);
    const std::vector<CornerRing> loops = part_boundary(face.whole);
    const Region region = test::region_of(shape.polygon);
    REQUIRE(region.loop_count() == static_cast<int>(loops.size()));
    for (int l = 0; l < region.loop_count(); ++l) {
      const Ring& ring = region.loop(l);
      for (size_t k = 0; k < ring.size(); ++k) {
        // The grid corner at this vertex (loops in the same order: the outer one, then the holes
        // sorted alike is not promised, so every loop is searched).
        bool found = false;
        for (size_t gl = 0; gl < loops.size() && !found; ++gl) {
          for (size_t gk = 0; gk < loops[gl].size() && !found; ++gk) {
            const Corner& c = loops[gl][gk];
            const Point2 p{face.grid->xs[static_cast<size_t>(c.i)], face.grid->ys[static_cast<size_t>(c.j)]};
            if (std::fabs(p.x - ring[k].x) > region.quantum() || std::fabs(p.y - ring[k].y) > region.quantum()) continue;
            found = true;
            const Observation grid = observe_vertex(face.whole, loops, static_cast<int>(gl), static_cast<int>(gk));
            const Observation general = observe_region_vertex(region, l, static_cast<int>(k));
            for (int n = 0; n < kObservationSize; ++n) {
              CHECK(general[static_cast<size_t>(n)] == Approx(grid[static_cast<size_t>(n)]).margin(1e-5));
            }
            ++compared;
          }
        }
        CHECK(found);
      }
    }
  }
  CHECK(compared > 200);
}

TEST_CASE("region observations: true angles, bounded, independent of units and position", "[region][observation]") {
  // Generated polygons and chamfered unions with and without holes: the interior angles of a loop of
  // n vertices sum to (n - 2) 180 degrees (the outer one) or (n + 2) 180 (a hole, seen from the
  // part); every number in [-1, 1]; the same face drawn 1000 times larger elsewhere, the same numbers.
  for (int i = 0; i < 16; ++i) {
    const RectilinearPolygon polygon = test::general_polygon(500 + i, i % 2 ? GeneralKind::Chamfered : GeneralKind::Polygon, i % 4 < 2);
    const Region region = test::region_of(polygon);
    RectilinearPolygon moved;
    for (const Point2& p : polygon.outer) moved.outer.push_back({1000.0 * p.x + 3.0, 1000.0 * p.y - 8.0});
    for (const Ring& hole : polygon.holes) {
      Ring& h = moved.holes.emplace_back();
      for (const Point2& p : hole) h.push_back({1000.0 * p.x + 3.0, 1000.0 * p.y - 8.0});
    }
    const Region big = test::region_of(moved);
    REQUIRE(big.loop_count() == region.loop_count());
    for (int l = 0; l < region.loop_count(); ++l) {
      const Ring& ring = region.loop(l);
      REQUIRE(big.loop(l).size() == ring.size());
      double sum = 0.0;
      for (size_t k = 0; k < ring.size(); ++k) {
        sum += region_interior_angle(region, l, static_cast<int>(k));
        const Observation o = observe_region_vertex(region, l, static_cast<int>(k));
        const Observation b = observe_region_vertex(big, l, static_cast<int>(k));
        for (int n = 0; n < kObservationSize; ++n) {
          CHECK(std::abs(o[static_cast<size_t>(n)]) <= 1.0f);
          CHECK(b[static_cast<size_t>(n)] == Approx(o[static_cast<size_t>(n)]).margin(1e-4));
        }
        CHECK(o[6] > 0.0f);
        CHECK(o[6] < 1.0f);
      }
      const double n = static_cast<double>(ring.size());
      CHECK(sum == Approx((l == 0 ? n - 2.0 : n + 2.0) * 180.0));
    }
  }
}
