#include <catch2/catch.hpp>

#include <BRepBndLib.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRep_Builder.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>
#include <gp_Vec.hxx>

#include <random>
#include <string>

#include "core/common/error.h"
#include "core/data/arc_generator.h"
#include "core/geometry/occt_properties.h"
#include "core/geometry/occt_face.h"
#include "support/bad_shapes.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;

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

namespace {

// The message planar_face_from_occt gives for face, or "" when it accepts the face.
std::string rejection(const TopoDS_Face& face) {
  try {
    planar_face_from_occt(face);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("the chamfered top face of a box is rejected with coordinates as a CAD user writes them",
          "[geometry][occt][errors][format]") {
  // An 83 x 40 x 10 box with its vertical edge at (83, 0) chamfered by 3, by a boolean cut along the plane
  // y = x - 80: the top face has a slanted edge from (80, 0) to (83, 3).
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(83, 40, 10).Shape();
  const TopoDS_Shape corner =
      BRepPrimAPI_MakePrism(TopoDS::Face(test::raw_polygon_face({{79, -1}, {85, -1}, {85, 5}}, -1)), gp_Vec(0, 0, 12))
          .Shape();
  BRepAlgoAPI_Cut chamfer(box, corner);
  REQUIRE(chamfer.IsDone());
  std::string message;
  for (TopExp_Explorer faces(chamfer.Shape(), TopAbs_FACE); faces.More(); faces.Next()) {
    const TopoDS_Face face = TopoDS::Face(faces.Current());
    Bnd_Box bounds;
    BRepBndLib::Add(face, bounds);
    if (bounds.CornerMin().Z() > 9.99 && bounds.CornerMax().Z() < 10.01) message = rejection(face);
  }
  INFO(message);
  CHECK_THAT(message, Contains("is not parallel to the X or Y axis"));
  CHECK_THAT(message, Contains("(80, 0)"));
  CHECK_THAT(message, Contains("(83, 3)"));
  CHECK_THAT(message, !Contains("e+") && !Contains("e-"));
}

TEST_CASE("coordinate noise far below the face's tolerance reads 0 in messages", "[geometry][occt][errors][format]") {
  // The same outline by hand, with the noise OpenCASCADE's operations leave in a coordinate.
  const std::string message = rejection(TopoDS::Face(
      test::raw_polygon_face({{0, 0}, {80, -2.22044604925031e-15}, {83, 3.0000000000000004}, {83, 40}, {0, 40}}, 10)));
  CHECK(message == "edge 2 of the outer wire, from (80, 0) to (83, 3), is not parallel to the X or Y axis");
  // A curved edge is named the same way, with its article.
  const std::string arc = rejection(TopoDS::Face(test::bad_shapes()[0].shape));
  CHECK_THAT(arc, Contains("is an elliptical arc; only straight edges and circular arcs are supported"));
  CHECK_THAT(arc, !Contains("e+") && !Contains("e-"));
}

TEST_CASE("a vertex off the face's plane within its own OpenCASCADE tolerance is on it", "[geometry][occt][errors]") {
  // A 10 x 5 rectangle in z = 0 whose corner (10, 5) lies 0.01 above the plane (as some STEP
  // translators leave vertices, with tolerances that say so).
  BRepBuilderAPI_MakePolygon polygon(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0), gp_Pnt(10, 5, 0.01), gp_Pnt(0, 5, 0), true);
  const TopoDS_Face face = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), polygon.Wire(), true).Face();
  const std::string message = rejection(face);
  CHECK(message == "a vertex of the face lies off its plane z = 0 by 0.01");
  // With the vertex's tolerance 0.02 the vertex is on the plane, and the face reads as the rectangle.
  BRep_Builder builder;
  for (TopExp_Explorer it(face, TopAbs_VERTEX); it.More(); it.Next()) {
    const TopoDS_Vertex v = TopoDS::Vertex(it.Current());
    if (BRep_Tool::Pnt(v).Z() > 0.005) builder.UpdateVertex(v, 0.02);
  }
  CHECK(rejection(face).empty());
  const PlanarFace read = planar_face_from_occt(face);
  CHECK(signed_area(read.polygon.outer) == Approx(50.0));
  CHECK(read.z == Approx(0.0));
}

TEST_CASE("face_from_rings makes generated faces with arcs again: valid, the same area and arcs", "[geometry][occt][arc]") {
  std::mt19937_64 rng(77);
  for (int k = 0; k < 30; ++k) {
    const ArcFace made = generate_arc_face(rng, ArcOptions{});
    for (const bool up : {true, false}) {
      TopoDS_Face face = made.face;
      if (!up) face.Reverse();
      const FaceRings read = read_face_rings(face);
      CHECK_FALSE(read.approximate);
      const TopoDS_Face again = face_from_rings(read);
      INFO(made.name << (up ? ", up" : ", down"));
      CHECK(occt_shape_valid(again));
      CHECK(occt_area(again) == Approx(occt_area(face)).epsilon(1e-9));
      const FaceRings reread = read_face_rings(again);
      CHECK(reread.normal_up == up);
      REQUIRE(reread.arcs.size() == read.arcs.size());
      for (size_t a = 0; a < read.arcs.size(); ++a) {
        CHECK(reread.arcs[a].sweep == Approx(read.arcs[a].sweep).epsilon(1e-9));
        CHECK(reread.arcs[a].radius == Approx(read.arcs[a].radius).epsilon(1e-9));
        CHECK(reread.arcs[a].outside == read.arcs[a].outside);
      }
      REQUIRE(reread.rings.size() == read.rings.size());
      for (size_t r = 0; r < read.rings.size(); ++r) CHECK(reread.rings[r].points.size() == read.rings[r].points.size());
    }
  }
}
