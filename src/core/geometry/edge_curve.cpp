#include "core/geometry/edge_curve.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax3.hxx>
#include <gce_MakeCirc.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <optional>
#include <cmath>
#include <vector>

namespace autoblock {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The edge's samples in its curve's own direction, its ends included.
std::vector<gp_Pnt> curve_samples(const BRepAdaptor_Curve& curve) {
  const double u0 = curve.FirstParameter(), u1 = curve.LastParameter();
  std::vector<gp_Pnt> points;
  for (int k = 0; k <= kRecognitionSamples; ++k) points.push_back(curve.Value(u0 + (u1 - u0) * k / kRecognitionSamples));
  return points;
}

// The farthest sample from the chord between the ends, or infinity when the samples double back.
double line_deviation(const std::vector<gp_Pnt>& points, double tolerance) {
  const gp_Pnt a = points.front(), b = points.back();
  const gp_Vec chord(a, b);
  const double length = chord.Magnitude();
  if (length <= tolerance) return HUGE_VAL;
  const gp_Vec along = chord / length;
  double deviation = 0.0, last = -HUGE_VAL;
  for (const gp_Pnt& p : points) {
    const gp_Vec v(a, p);
    const double t = v.Dot(along);
    if (t < last - tolerance) return HUGE_VAL;
    last = std::max(last, t);
    deviation = std::max(deviation, (v - along * t).Magnitude());
  }
  return deviation;
}

// The angle of p about the circle in its own plane.
double angle_on(const gp_Circ& circle, const gp_Pnt& p) {
  const gp_Vec v(circle.Location(), p);
  return std::atan2(v.Dot(gp_Vec(circle.YAxis().Direction())), v.Dot(gp_Vec(circle.XAxis().Direction())));
}

double wrapped(double a) {
  while (a > kPi) a -= 2 * kPi;
  while (a < -kPi) a += 2 * kPi;
  return a;
}

// The farthest sample from the circle through three of them (or infinity when there is none, or the
// samples do not run round it one way).
double circle_deviation(const std::vector<gp_Pnt>& points, bool closed, gp_Circ* circle) {
  const size_t n = points.size() - 1;
  const gce_MakeCirc make = closed ? gce_MakeCirc(points[0], points[n / 3], points[2 * n / 3])
                                   : gce_MakeCirc(points[0], points[n / 2], points[n]);
  if (!make.IsDone()) return HUGE_VAL;
  *circle = make.Value();
  const gp_Vec normal(circle->Axis().Direction());
  double deviation = 0.0, direction = 0.0;
  for (size_t k = 0; k < points.size(); ++k) {
    const gp_Vec v(circle->Location(), points[k]);
    const double off_plane = v.Dot(normal);
    const double in_plane = (v - normal * off_plane).Magnitude();
    deviation = std::max(deviation, std::hypot(off_plane, in_plane - circle->Radius()));
    if (k == 0) continue;
    const double step = wrapped(angle_on(*circle, points[k]) - angle_on(*circle, points[k - 1]));
    if (step == 0.0) continue;
    if (direction == 0.0) direction = step;
    if ((step > 0) != (direction > 0)) return HUGE_VAL;
  }
  return deviation;
}

}  // namespace

EdgeCurve edge_curve(const TopoDS_Edge& edge, double face_size) {
  const BRepAdaptor_Curve curve(edge);
  EdgeCurve result;
  result.stored = curve.GetType();
  if (result.stored == GeomAbs_Line) {
    result.shape = EdgeShape::Line;
    return result;
  }
  if (result.stored == GeomAbs_Circle) {
    result.shape = EdgeShape::Circle;
    result.circle = curve.Circle();
    return result;
  }
  if (result.stored != GeomAbs_BSplineCurve && result.stored != GeomAbs_BezierCurve) return result;
  result.tolerance = std::max(BRep_Tool::Tolerance(edge), kRecognitionRelative * face_size);
  const std::vector<gp_Pnt> points = curve_samples(curve);
  const bool closed = points.front().Distance(points.back()) <= result.tolerance;
  const double line = closed ? HUGE_VAL : line_deviation(points, result.tolerance);
  gp_Circ circle;
  const double round = circle_deviation(points, closed, &circle);
  result.deviation = std::min(line, round);
  if (line <= result.tolerance) {
    result.shape = EdgeShape::Line;
  } else if (round <= result.tolerance) {
    result.shape = EdgeShape::Circle;
    result.circle = circle;
  }
  return result;
}

double circle_edge_sweep(const TopoDS_Edge& edge, const gp_Circ& circle) {
  const BRepAdaptor_Curve curve(edge);
  const bool reversed = edge.Orientation() == TopAbs_REVERSED;
  if (curve.GetType() == GeomAbs_Circle) {
    // The circle's own parameter is its angle: exact, a full circle's 2 pi included.
    const double turn = reversed ? curve.FirstParameter() - curve.LastParameter() : curve.LastParameter() - curve.FirstParameter();
    return (curve.Circle().Axis().Direction().Z() > 0 ? 1.0 : -1.0) * turn;
  }
  std::vector<gp_Pnt> points = curve_samples(curve);
  if (reversed) std::reverse(points.begin(), points.end());
  const gp_Pnt c = circle.Location();
  double sweep = 0.0;
  for (size_t k = 1; k < points.size(); ++k) {
    sweep += wrapped(std::atan2(points[k].Y() - c.Y(), points[k].X() - c.X()) -
                     std::atan2(points[k - 1].Y() - c.Y(), points[k - 1].X() - c.X()));
  }
  // A closed edge runs the whole circle.
  if (std::fabs(std::fabs(sweep) - 2 * kPi) < 1e-6) sweep = sweep > 0 ? 2 * kPi : -2 * kPi;
  return sweep;
}

bool face_cylinder(const TopoDS_Face& face, gp_Cylinder* cylinder) {
  const BRepAdaptor_Surface surface(face);
  if (surface.GetType() == GeomAbs_Cylinder) {
    *cylinder = surface.Cylinder();
    return true;
  }
  if (surface.GetType() != GeomAbs_BSplineSurface && surface.GetType() != GeomAbs_BezierSurface) return false;
  double tolerance = BRep_Tool::Tolerance(face), size = 0.0;
  std::vector<TopoDS_Edge> edges;
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge edge = TopoDS::Edge(it.Current());
    if (BRep_Tool::Degenerated(edge)) continue;
    edges.push_back(edge);
    tolerance = std::max(tolerance, BRep_Tool::Tolerance(edge));
    const BRepAdaptor_Curve curve(edge);
    size = std::max(size, curve.Value(curve.FirstParameter()).Distance(curve.Value(curve.LastParameter())));
  }
  std::vector<EdgeCurve> shapes;
  for (const TopoDS_Edge& edge : edges) shapes.push_back(edge_curve(edge, size));
  // The axis's direction from a straight edge, the circle from a circular one square to it.
  std::optional<gp_Dir> axis;
  for (size_t k = 0; k < edges.size() && !axis; ++k) {
    if (shapes[k].shape != EdgeShape::Line) continue;
    const BRepAdaptor_Curve curve(edges[k]);
    const gp_Vec along(curve.Value(curve.FirstParameter()), curve.Value(curve.LastParameter()));
    if (along.Magnitude() > tolerance) axis = gp_Dir(along);
  }
  if (!axis) return false;
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  for (const EdgeCurve& curve : shapes) {
    if (curve.shape != EdgeShape::Circle) continue;
    if (std::fabs(std::fabs(curve.circle.Axis().Direction().Dot(*axis)) - 1.0) > 1e-6) continue;
    const double limit = std::max(tolerance, kRecognitionRelative * 2.0 * curve.circle.Radius());
    bool on = true;
    for (int i = 0; i <= 8 && on; ++i) {
      for (int j = 0; j <= 8 && on; ++j) {
        const gp_Pnt p = surface.Value(u0 + (u1 - u0) * i / 8.0, v0 + (v1 - v0) * j / 8.0);
        gp_Vec radial(curve.circle.Location(), p);
        radial -= gp_Vec(*axis) * radial.Dot(gp_Vec(*axis));
        on = std::fabs(radial.Magnitude() - curve.circle.Radius()) <= limit;
      }
    }
    if (on) {
      *cylinder = gp_Cylinder(gp_Ax3(curve.circle.Location(), *axis), curve.circle.Radius());
      return true;
    }
  }
  return false;
}

}  // namespace autoblock
