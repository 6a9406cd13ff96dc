#include <catch2/catch.hpp>

#include "core/geometry/axis_cut.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {
Ring u_shape() { return {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}; }

double total_area(const std::vector<Part>& pieces) {
  double a = 0;
  for (const Part& p : pieces) a += p.area();
  return a;
}
}  // namespace

TEST_CASE("a full cut through the L-shape's re-entrant corner leaves two rectangles", "[geometry]") {
  const GridFace face = test::grid_face_of(test::l_shape());
  const auto horizontal = cut_part(face.whole, AxisLine{CutDirection::Horizontal, 1});
  REQUIRE(horizontal.size() == 2);
  CHECK(horizontal[0].bbox().width() == 2);  // bottom bar first (lowest cell)
  CHECK(horizontal[0].bbox().height() == 1);
  CHECK(horizontal[1].area() == 1);
  for (const Part& p : horizontal) CHECK(p.is_rectangle());
  const auto vertical = cut_part(face.whole, AxisLine{CutDirection::Vertical, 1});
  REQUIRE(vertical.size() == 2);
  CHECK(vertical[0].bbox().height() == 2);  // left column holds the lowest-left cell
  CHECK(total_area(vertical) == 3);
}

TEST_CASE("the full line through a convex corner can split the part elsewhere", "[geometry]") {
  // The horizontal line through the convex corner (2,1) runs along an edge there but through
  // the interior for 0 < x < 1.
  const GridFace face = test::grid_face_of(test::l_shape());
  CHECK(line_crosses_interior(face.whole, AxisLine{CutDirection::Horizontal, 1}));
  CHECK(cut_part(face.whole, AxisLine{CutDirection::Horizontal, 1}).size() == 2);
}

TEST_CASE("a line along the boundary only changes nothing (N = 1)", "[geometry]") {
  const GridFace face = test::grid_face_of(test::l_shape());
  for (const AxisLine line : {AxisLine{CutDirection::Horizontal, 0}, AxisLine{CutDirection::Vertical, 2},
                              AxisLine{CutDirection::Horizontal, 2}}) {
    CHECK_FALSE(line_crosses_interior(face.whole, line));
    const auto pieces = cut_part(face.whole, line);
    REQUIRE(pieces.size() == 1);
    CHECK(pieces[0] == face.whole);
  }
}

TEST_CASE("one cut can leave three pieces", "[geometry]") {
  const GridFace face = test::grid_face_of(u_shape());
  const auto pieces = cut_part(face.whole, AxisLine{CutDirection::Horizontal, 1});
  REQUIRE(pieces.size() == 3);
  CHECK(pieces[0].area() == 3);
  CHECK(pieces[1].area() == 1);
  CHECK(pieces[2].area() == 1);
  for (const Part& p : pieces) CHECK(p.is_rectangle());
}

TEST_CASE("cutting through a hole opens it", "[geometry]") {
  const GridFace face = test::grid_face_of(test::square3(), {test::centre_hole()});
  const auto pieces = cut_part(face.whole, AxisLine{CutDirection::Vertical, 1});
  REQUIRE(pieces.size() == 2);
  CHECK(pieces[0].is_rectangle());  // [0,1] x [0,3]
  CHECK(pieces[0].area() == 3);
  CHECK_FALSE(pieces[1].is_rectangle());  // the C-shape [1,3] x [0,3] minus the hole
  CHECK(pieces[1].area() == 5);
}

TEST_CASE("parts compare and hash by their cells", "[geometry]") {
  const GridFace face = test::grid_face_of(test::l_shape());
  const auto a = cut_part(face.whole, AxisLine{CutDirection::Horizontal, 1});
  const auto b = cut_part(face.whole, AxisLine{CutDirection::Horizontal, 1});
  CHECK(a[0] == b[0]);
  CHECK(a[0].hash() == b[0].hash());
  CHECK_FALSE(a[0] == a[1]);
}
