#include <catch2/catch.hpp>


#include "core/geometry/occt_properties.h"
#include "core/geometry/occt_face.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("occt_face_from_polygon builds a valid face with the exact area", "[geometry][occt]") {
  const RectilinearPolygon polygon = test::polygon_of(test::square3(), {test::centre_hole()});
  const TopoDS_Face face = occt_face_from_polygon(polygon, -4.0, true);
  REQUIRE_FALSE(face.IsNull());
  CHECK(occt_shape_valid(face));
  CHECK(occt_area(face) == Approx(8.0));
}

TEST_CASE("planar_face_from_occt reads back the polygon, plane and normal", "[geometry][occt]") {
  const RectilinearPolygon polygon = test::polygon_of(test::l_shape());
  for (bool up : {true, false}) {
    const PlanarFace read = planar_face_from_occt(occt_face_from_polygon(polygon, 7.25, up));
    CHECK(read.z == Approx(7.25));
    CHECK(read.normal_up == up);
    CHECK(read.polygon.outer.size() == 6);
    CHECK(signed_area(read.polygon.outer) == Approx(3.0));
  }
}

TEST_CASE("generated faces survive the trip to OpenCASCADE and back", "[geometry][occt]") {
  GeneratorOptions options;
  options.holes = true;
  for (const GeneratedShape& shape : test::generated_shapes(40, 5, options)) {
    const TopoDS_Face face = occt_face_from_polygon(shape.polygon, 0, true);
    REQUIRE(occt_shape_valid(face));
    CHECK(occt_area(face) == Approx(polygon_area(shape.polygon)));
    const PlanarFace read = planar_face_from_occt(face);
    CHECK(read.polygon.outer.size() == shape.polygon.outer.size());
    CHECK(read.polygon.holes.size() == shape.polygon.holes.size());
  }
}
