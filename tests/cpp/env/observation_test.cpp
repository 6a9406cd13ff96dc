#include <catch2/catch.hpp>

#include "core/env/observation.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("the observation at the L-shape's re-entrant corner, by hand", "[env][observation]") {
  // Vertex v = (1,1) is corner 3 of the outer loop: previous (2,1), next (1,2); s = 2.
  // Centroid of the three unit cells centred at (0.5,0.5), (1.5,0.5), (0.5,1.5) is (5/6, 5/6).
  //   (p - v)/s = (0.5, 0)   (n - v)/s = (0, 0.5)   (c - v)/s = (-1/12, -1/12)
  //   angle 270/360 = 0.75   W/s = H/s = 1
  const GridFace face = test::grid_face_of(test::l_shape());
  const auto loops = part_boundary(face.whole);
  const Observation o = observe_vertex(face.whole, loops, 0, 3);
  const std::vector<double> expected{0.5, 0, 0, 0.5, -1.0 / 12, -1.0 / 12, 0.75, 1, 1};
  for (int k = 0; k < kObservationSize; ++k) CHECK(o[static_cast<size_t>(k)] == Approx(expected[static_cast<size_t>(k)]));
}

TEST_CASE("the observation at a convex corner of a 4x1 bar", "[env][observation]") {
  // v = (0,0): previous (0,1), next (4,0), s = 4, centroid (2, 0.5).
  const GridFace face = test::grid_face_of({{0, 0}, {4, 0}, {4, 1}, {0, 1}});
  const auto loops = part_boundary(face.whole);
  const Observation o = observe_vertex(face.whole, loops, 0, 0);
  const std::vector<double> expected{0, 0.25, 1, 0, 0.5, 0.125, 0.25, 1, 0.25};
  for (int k = 0; k < kObservationSize; ++k) CHECK(o[static_cast<size_t>(k)] == Approx(expected[static_cast<size_t>(k)]));
}

TEST_CASE("observations are scale- and translation-invariant and bounded", "[env][observation]") {
  GeneratorOptions options;
  options.holes = true;
  for (const GeneratedShape& shape : test::generated_shapes(20, 3, options)) {
    Ring outer;
    for (const Point2& p : shape.polygon.outer) outer.push_back({p.x * 0.001 + 5, p.y * 0.001 - 7});
    std::vector<Ring> holes;
    for (const Ring& hole : shape.polygon.holes) {
      Ring h;
      for (const Point2& p : hole) h.push_back({p.x * 0.001 + 5, p.y * 0.001 - 7});
      holes.push_back(h);
    }
    const GridFace a = make_grid_face(shape.polygon);
    const GridFace b = test::grid_face_of(outer, holes);
    const auto la = part_boundary(a.whole), lb = part_boundary(b.whole);
    for (size_t l = 0; l < la.size(); ++l) {
      for (size_t k = 0; k < la[l].size(); ++k) {
        const Observation oa = observe_vertex(a.whole, la, static_cast<int>(l), static_cast<int>(k));
        const Observation ob = observe_vertex(b.whole, lb, static_cast<int>(l), static_cast<int>(k));
        for (int n = 0; n < kObservationSize; ++n) {
          CHECK(oa[static_cast<size_t>(n)] == Approx(ob[static_cast<size_t>(n)]).margin(1e-5));
          CHECK(std::abs(oa[static_cast<size_t>(n)]) <= 1.0f);
        }
      }
    }
  }
}
