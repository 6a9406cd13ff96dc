#include <catch2/catch.hpp>

#include "core/baselines/min_rectangles.h"
#include "core/baselines/optimal_search.h"
#include "core/geometry/part_boundary.h"
#include "core/geometry/part_symmetry.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("the square's symmetries keep areas, corners, optimal values and block minima", "[geometry][symmetry]") {
  GeneratorOptions options;
  options.holes = true;
  for (const GeneratedShape& shape : test::generated_shapes(20, 21, options)) {
    const GridFace face = make_grid_face(shape.polygon);
    const double value = OptimalSearch(face.size, 0).value(face.whole);
    size_t corners = 0;
    for (const auto& loop : part_boundary(face.whole)) corners += loop.size();
    for (int s = 0; s < 8; ++s) {
      INFO("symmetry " << s);
      const Part image = transform_part(face.whole, s);
      CHECK(image.area() == Approx(face.whole.area()));
      size_t image_corners = 0;
      for (const auto& loop : part_boundary(image)) image_corners += loop.size();
      CHECK(image_corners == corners);
      CHECK(OptimalSearch(face.size, 0).value(image) == Approx(value));
      CHECK(min_rectangles(image) == min_rectangles(face.whole));
    }
  }
}

TEST_CASE("a quarter turn maps the L-shape's cells as (x, y) -> (-y, x)", "[geometry][symmetry]") {
  // L cells (0,0), (1,0), (0,1) of the unit grid; turned: x' = -y, y' = x, so the bounding box
  // [0,2]x[0,2] becomes [-2,0]x[0,2] and the missing cell (1,1) becomes the one at (-2..-1, 1..2).
  const GridFace face = test::grid_face_of(test::l_shape());
  const Part turned = transform_part(face.whole, 2);
  const Box box = turned.bbox();
  CHECK(box.xmin == -2);
  CHECK(box.xmax == 0);
  CHECK(box.ymin == 0);
  CHECK(box.ymax == 2);
  CHECK_FALSE(turned.contains(0, 1));  // the cell [-2,-1] x [1,2]
  CHECK(turned.contains(1, 1));
  CHECK(transform_part(face.whole, 0).area() == face.whole.area());
  CHECK(transform_part(transform_part(face.whole, 1), 1).bbox().xmin == box.ymin);  // a mirror twice: back
}
