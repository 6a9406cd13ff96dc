// Edges stored as B-spline or Bezier curves that are lines or circles (edge_curve.h): read as what
// they are within the recognition tolerance, and refused, with the deviation named, when they are not.
#include <catch2/catch.hpp>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Vec.hxx>

#include <cmath>
#include <string>

#include "core/common/error.h"
#include "core/data/arc_generator.h"
#include "core/geometry/edge_curve.h"
#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"
#include "core/io/input_face.h"

using namespace autoblock;
using Catch::Matchers::Contains;

namespace {

// A "D": the segment from (10, 0) back to (0, 0) below, and above it the half circle of radius 5 about
// (5, 0) as a B-spline interpolating 65 of its points, pushed out radially by wobble * sin(2 theta)
// (0 at its ends and middle, which the recognised circle passes through; +-wobble between).
TopoDS_Face d_face(double wobble) {
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, 65);
  for (int k = 0; k < 65; ++k) {
    const double theta = M_PI * k / 64.0;
    const double r = 5.0 + wobble * std::sin(2 * theta);
    points->SetValue(k + 1, gp_Pnt(5 + r * std::cos(theta), r * std::sin(theta), 0));
  }
  GeomAPI_Interpolate interpolate(points, false, 1e-9);
  interpolate.Perform();
  REQUIRE(interpolate.IsDone());
  const TopoDS_Edge arc = BRepBuilderAPI_MakeEdge(interpolate.Curve());
  const TopoDS_Edge base = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0));
  BRepBuilderAPI_MakeWire wire(base, arc);
  REQUIRE(wire.IsDone());
  BRepBuilderAPI_MakeFace face(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), wire.Wire());
  REQUIRE(face.IsDone());
  return face.Face();
}

TopoDS_Edge curved_edge(const TopoDS_Face& face) {
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge edge = TopoDS::Edge(it.Current());
    if (BRepAdaptor_Curve(edge).GetType() != GeomAbs_Line) return edge;
  }
  FAIL("the face has no curved edge");
  return TopoDS_Edge();
}

}  // namespace

TEST_CASE("edge_curve: a B-spline within its tolerance of a circle is that circle", "[geometry][occt][arc]") {
  // The recognition tolerance here: the larger of the edge's (1e-7) and 1e-6 of the face's size 10.
  const TopoDS_Face close = d_face(1e-7);
  const EdgeCurve read = edge_curve(curved_edge(close), 10.0);
  INFO("deviation " << read.deviation);
  CHECK(read.stored == GeomAbs_BSplineCurve);
  REQUIRE(read.shape == EdgeShape::Circle);
  CHECK(read.recognised());
  CHECK(read.tolerance == Approx(1e-5));
  CHECK(read.deviation < 1e-5);
  CHECK(read.circle.Radius() == Approx(5.0).epsilon(1e-9));
  CHECK(read.circle.Location().Distance(gp_Pnt(5, 0, 0)) < 1e-9);
  CHECK(circle_edge_sweep(curved_edge(close), read.circle) == Approx(M_PI).epsilon(1e-9));

  // The face reads as a half disk: one arc, the face inside its circle, its area the half disk's.
  const InputFace face = input_face_from_occt(close, "D");
  REQUIRE(face.arcs.arcs.size() == 1);
  const CircularArc& arc = face.arcs.arcs[0];
  CHECK(arc.radius == Approx(5.0));
  CHECK(std::fabs(arc.sweep) == Approx(M_PI));
  CHECK_FALSE(arc.outside);
  CHECK(arc.first().x == Approx(10.0));
  CHECK(arc.last().x == Approx(0.0).margin(1e-9));
}

TEST_CASE("edge_curve: a B-spline off every circle by more than the tolerance is refused, the deviation named",
          "[geometry][occt][arc][errors]") {
  const TopoDS_Face wobbly = d_face(1e-3);
  const EdgeCurve read = edge_curve(curved_edge(wobbly), 10.0);
  CHECK(read.shape == EdgeShape::Other);
  CHECK(read.deviation > 5e-4);
  CHECK(read.deviation < 2e-3);
  std::string message;
  try {
    input_face_from_occt(wobbly, "wobbly D");
  } catch (const InputError& e) {
    message = e.what();
  }
  INFO(message);
  CHECK_THAT(message, Contains("is a B-spline curve that is neither a straight line nor a circular arc within its tolerance 1e-5"));
  CHECK_THAT(message, Contains("it strays 0.001"));
  CHECK_THAT(message, Contains("from (10, 0) to (0, 0)"));

  // The same curve with an edge tolerance that covers the wobble (as a translator sets it to its
  // approximation's error) is the circle.
  BRep_Builder builder;
  const TopoDS_Edge edge = curved_edge(wobbly);
  builder.UpdateEdge(edge, 2e-3);
  TopoDS_Vertex a, b;
  TopExp::Vertices(edge, a, b);
  builder.UpdateVertex(a, 2e-3);
  builder.UpdateVertex(b, 2e-3);
  const EdgeCurve loose = edge_curve(edge, 10.0);
  CHECK(loose.shape == EdgeShape::Circle);
  CHECK(loose.tolerance == Approx(2e-3));
}

TEST_CASE("edge_curve: a face converted wholly to NURBS reads as the same face", "[geometry][occt][arc]") {
  // A plate with two round holes, its plane, lines and circles all turned into B-splines (as some
  // translators write every curve).
  const TopoDS_Face plate = plate_with_holes(12, 8, {{3.5, 4, 1.5}, {8.5, 4, 1.0}});
  BRepBuilderAPI_NurbsConvert convert(plate, true);
  const TopoDS_Face nurbs = TopoDS::Face(convert.Shape());
  int bsplines = 0;
  for (TopExp_Explorer it(nurbs, TopAbs_EDGE); it.More(); it.Next()) {
    bsplines += BRepAdaptor_Curve(TopoDS::Edge(it.Current())).GetType() == GeomAbs_BSplineCurve;
  }
  REQUIRE(bsplines >= 6);
  const InputFace original = input_face_from_occt(plate, "plate");
  const InputFace read = input_face_from_occt(nurbs, "NURBS plate");
  REQUIRE(read.arcs.arcs.size() == original.arcs.arcs.size());
  for (size_t k = 0; k < read.arcs.arcs.size(); ++k) {
    const CircularArc &p = read.arcs.arcs[k], &q = original.arcs.arcs[k];
    CHECK(p.radius == Approx(q.radius).epsilon(1e-9));
    CHECK(p.center.x == Approx(q.center.x).epsilon(1e-9));
    CHECK(p.center.y == Approx(q.center.y).epsilon(1e-9));
    CHECK(p.sweep == Approx(q.sweep).epsilon(1e-9));
    CHECK(p.outside == q.outside);
  }
  CHECK(read.region.area() == Approx(original.region.area()).epsilon(1e-9));
  CHECK(read.region.outer().size() == original.region.outer().size());
  // The straight sides are lines to the frame too: the plate keeps the model's axes.
  CHECK(read.frame.identity());
}

TEST_CASE("face_cylinder: a B-spline surface that is a cylinder is one, a plane or a cone is not", "[geometry][occt][arc]") {
  const TopoDS_Shape drilled = BRepPrimAPI_MakePrism(plate_with_holes(12, 8, {{3, 4, 1.5}}), gp_Vec(0, 0, 2.5)).Shape();
  const TopoDS_Shape nurbs = BRepBuilderAPI_NurbsConvert(drilled, true).Shape();
  int walls = 0, flat = 0;
  for (TopExp_Explorer it(nurbs, TopAbs_FACE); it.More(); it.Next()) {
    const TopoDS_Face face = TopoDS::Face(it.Current());
    gp_Cylinder cylinder;
    if (!face_cylinder(face, &cylinder)) {
      ++flat;
      continue;
    }
    ++walls;
    CHECK(cylinder.Radius() == Approx(1.5).epsilon(1e-9));
    CHECK(std::fabs(cylinder.Axis().Direction().Z()) == Approx(1.0));
    CHECK(std::hypot(cylinder.Location().X() - 3, cylinder.Location().Y() - 4) < 1e-9);
  }
  CHECK(walls >= 1);
  CHECK(flat == 6);
  // A cone's wall, stored as a B-spline, is no cylinder.
  const TopoDS_Shape cone = BRepBuilderAPI_NurbsConvert(BRepPrimAPI_MakeCone(2.0, 1.0, 3.0).Shape(), true).Shape();
  for (TopExp_Explorer it(cone, TopAbs_FACE); it.More(); it.Next()) {
    gp_Cylinder cylinder;
    CHECK_FALSE(face_cylinder(TopoDS::Face(it.Current()), &cylinder));
  }
}
