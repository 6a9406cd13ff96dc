#include <catch2/catch.hpp>


#include "core/geometry/occt_properties.h"
#include "core/geometry/occt_face.h"
#include "core/geometry/occt_split.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("split_face_along_line cuts the L-shape into two valid rectangles", "[geometry][occt]") {
  const TopoDS_Face face = occt_face_from_polygon(test::polygon_of(test::l_shape()), 1.0, true);
  const auto pieces = split_face_along_line(face, CutDirection::Horizontal, 1.0);
  REQUIRE(pieces.size() == 2);
  double total = 0;
  for (const TopoDS_Face& piece : pieces) {
    CHECK(occt_shape_valid(piece));
    CHECK(occt_vertex_count(piece) == 4);  // collinear edges merged
    total += occt_area(piece);
  }
  CHECK(total == Approx(3.0));
}

TEST_CASE("split_face_along_line along the boundary gives the face back", "[geometry][occt]") {
  const TopoDS_Face face = occt_face_from_polygon(test::polygon_of(test::l_shape()), 0.0, true);
  const auto pieces = split_face_along_line(face, CutDirection::Vertical, 2.0);
  REQUIRE(pieces.size() == 1);
  CHECK(occt_area(pieces[0]) == Approx(3.0));
  CHECK(occt_vertex_count(pieces[0]) == 6);
}

TEST_CASE("split_face_along_line through a hole gives two C-shapes", "[geometry][occt]") {
  const TopoDS_Face face = occt_face_from_polygon(test::polygon_of(test::square3(), {test::centre_hole()}), 0.0, true);
  const auto pieces = split_face_along_line(face, CutDirection::Vertical, 1.5);
  REQUIRE(pieces.size() == 2);
  for (const TopoDS_Face& piece : pieces) {
    CHECK(occt_shape_valid(piece));
    CHECK(occt_vertex_count(piece) == 8);
    CHECK(occt_area(piece) == Approx(4.0));
  }
}
