#include <catch2/catch.hpp>

#include "core/geometry/part_boundary.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("part_boundary lists the L-shape's corners counter-clockwise from the lowest-left one", "[geometry]") {
  const GridFace face = test::grid_face_of(test::l_shape());
  const auto loops = part_boundary(face.whole);
  REQUIRE(loops.size() == 1);
  // Grid: xs = ys = {0, 1, 2}, so grid indices equal coordinates.
  const std::vector<std::tuple<int, int, bool>> expected{{0, 0, false}, {2, 0, false}, {2, 1, false},
                                                         {1, 1, true},  {1, 2, false}, {0, 2, false}};
  REQUIRE(loops[0].size() == expected.size());
  for (size_t k = 0; k < expected.size(); ++k) {
    CHECK(loops[0][k].i == std::get<0>(expected[k]));
    CHECK(loops[0][k].j == std::get<1>(expected[k]));
    CHECK(loops[0][k].reflex == std::get<2>(expected[k]));
  }
}

TEST_CASE("part_boundary walks holes clockwise, and their corners are re-entrant", "[geometry]") {
  const GridFace face = test::grid_face_of(test::square3(), {test::centre_hole()});
  const auto loops = part_boundary(face.whole);
  REQUIRE(loops.size() == 2);
  CHECK(loops[0].size() == 4);
  for (const Corner& c : loops[0]) CHECK_FALSE(c.reflex);
  REQUIRE(loops[1].size() == 4);
  // Clockwise from (1,1): up to (1,2), right to (2,2), down to (2,1).
  CHECK((loops[1][0].i == 1 && loops[1][0].j == 1));
  CHECK((loops[1][1].i == 1 && loops[1][1].j == 2));
  CHECK((loops[1][2].i == 2 && loops[1][2].j == 2));
  CHECK((loops[1][3].i == 2 && loops[1][3].j == 1));
  for (const Corner& c : loops[1]) CHECK(c.reflex);
}

TEST_CASE("make_grid_face reproduces generated polygons exactly", "[geometry]") {
  GeneratorOptions options;
  for (bool holes : {false, true}) {
    options.holes = holes;
    for (const GeneratedShape& shape : test::generated_shapes(100, holes ? 2 : 1, options)) {
      const GridFace face = make_grid_face(shape.polygon);
      CHECK(face.whole.area() == Approx(polygon_area(shape.polygon)));
      const auto loops = part_boundary(face.whole);
      REQUIRE(loops.size() == 1 + shape.polygon.holes.size());
      CHECK(loops[0].size() == shape.polygon.outer.size());
    }
  }
}
