// An edge's curve as AutoBlock reads it: a straight line, a circular arc, or neither.
//
// CAD systems and their STEP translators often write a circle, or a line, as a B-spline or Bezier
// curve (CATIA's drilled holes, a motor housing's bolt circles: about a fifth of the planar faces of
// the real parts measured in BENCHMARKS.md, "Real CAD faces"). Such an edge is read as the line or
// circle it is when every sample of it lies within the recognition tolerance of that line or circle:
// the larger of the edge's own tolerance (the distance within which OpenCASCADE guarantees its
// geometry, which a translator sets to its approximation's error) and kRecognitionRelative of the
// face's size. The line is the chord between the edge's ends; the circle passes through its ends and
// its middle (a closed edge: its start and its thirds), so the edge's vertices stay where they are.
// The mesh then puts its nodes on that circle: within the tolerance of the stored curve. Any other
// curve (an ellipse, a free-form spline) is Other, and refused with its deviation named.
#pragma once

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Circ.hxx>
#include <gp_Cylinder.hxx>

#include <GeomAbs_CurveType.hxx>

namespace autoblock {

// Samples along the edge that must lie within the tolerance (its ends included).
constexpr int kRecognitionSamples = 64;
// The recognition tolerance's floor, relative to the face's size.
constexpr double kRecognitionRelative = 1e-6;

enum class EdgeShape { Line, Circle, Other };

struct EdgeCurve {
  EdgeShape shape = EdgeShape::Other;
  GeomAbs_CurveType stored = GeomAbs_OtherCurve;  // the curve's type as stored (for messages)
  gp_Circ circle;  // Circle: the circle (a stored circle: its own)
  // A recognised or refused B-spline or Bezier curve: the farthest sample from the line or circle
  // tried (the nearer of the two), and the tolerance it was held to.
  double deviation = 0.0;
  double tolerance = 0.0;
  bool recognised() const { return stored != GeomAbs_Line && stored != GeomAbs_Circle && shape != EdgeShape::Other; }
};

// Inputs:  edge, a non-degenerate edge of a face; face_size, the longer side of the face's bounding box.
// Outputs: the edge's shape: a stored line or circle as itself; a B-spline or Bezier curve as a line
//          or circle when it is one within the tolerance (above); anything else Other.
EdgeCurve edge_curve(const TopoDS_Edge& edge, double face_size);

// Inputs:  edge, whose edge_curve is a Circle (circle).
// Outputs: the signed angle it turns through as the edge runs (its orientation counted), about the
//          circle's centre seen from +Z: > 0 counter-clockwise; +-2 pi for a closed edge.
double circle_edge_sweep(const TopoDS_Edge& edge, const gp_Circ& circle);

// Inputs:  face, any face.
// Outputs: true, and its cylinder, when its surface is a cylinder, or a B-spline or Bezier surface that
//          is one: a straight edge of the face gives the axis's direction, a circular edge square to it
//          (edge_curve) the axis and radius, and every point of a 9 x 9 grid over the face's parameters
//          lies within the recognition tolerance of that cylinder (the largest of the face's and its
//          edges' tolerances, and kRecognitionRelative of its diameter). A swept solid's hole written
//          as two B-spline half cylinders (CATIA) is so a hole.
bool face_cylinder(const TopoDS_Face& face, gp_Cylinder* cylinder);

}  // namespace autoblock
