#include "core/geometry/occt_face.h"

#include "core/geometry/occt_properties.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <Geom_Circle.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <TopLoc_Location.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GeomLib_IsPlanarSurface.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pln.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/common/format.h"
#include "core/geometry/circular_arc.h"
#include "core/geometry/edge_curve.h"
#include "core/geometry/tolerance.h"
#include "core/geometry/validate_polygon.h"

namespace autoblock {
namespace {

std::string surface_type_name(GeomAbs_SurfaceType type) {
  switch (type) {
    case GeomAbs_Plane: return "plane";
    case GeomAbs_Cylinder: return "cylinder";
    case GeomAbs_Cone: return "cone";
    case GeomAbs_Sphere: return "sphere";
    case GeomAbs_Torus: return "torus";
    case GeomAbs_BezierSurface: return "Bezier surface";
    case GeomAbs_BSplineSurface: return "B-spline surface";
    case GeomAbs_SurfaceOfRevolution: return "surface of revolution";
    case GeomAbs_SurfaceOfExtrusion: return "surface of extrusion";
    case GeomAbs_OffsetSurface: return "offset surface";
    default: return "general surface";
  }
}

std::string curve_type_name(GeomAbs_CurveType type) {
  switch (type) {
    case GeomAbs_Line: return "line";
    case GeomAbs_Circle: return "circular arc";
    case GeomAbs_Ellipse: return "elliptical arc";
    case GeomAbs_Hyperbola: return "hyperbola";
    case GeomAbs_Parabola: return "parabola";
    case GeomAbs_BezierCurve: return "Bezier curve";
    case GeomAbs_BSplineCurve: return "B-spline curve";
    case GeomAbs_OffsetCurve: return "offset curve";
    default: return "general curve";
  }
}

// The face's plane, if its surface is a plane or within 1e-7 of one.
bool plane_of(const TopoDS_Face& face, gp_Pln* plane) {
  BRepAdaptor_Surface surface(face, false);
  if (surface.GetType() == GeomAbs_Plane) {
    *plane = surface.Plane();
    return true;
  }
  GeomLib_IsPlanarSurface planar(BRep_Tool::Surface(face), 1e-7);
  if (!planar.IsPlanar()) return false;
  *plane = planar.Plan();
  return true;
}

gp_Pln face_plane(const TopoDS_Face& face) {
  gp_Pln plane;
  if (!plane_of(face, &plane)) {
    throw InputError("the face is not planar: its surface is " + with_article(surface_name(face)));
  }
  return plane;
}

// The longer side of the face's bounding box in X and Y (0 for an empty face): its tolerance
// (tolerance.h) for messages before its polygon is checked, and the recognition tolerance's scale.
double face_box_size(const TopoDS_Face& face) {
  Bnd_Box box;
  BRepBndLib::Add(face, box, false);
  if (box.IsVoid()) return 0.0;
  double xmin, ymin, zmin, xmax, ymax, zmax;
  box.Get(xmin, ymin, zmin, xmax, ymax, zmax);
  return std::max(xmax - xmin, ymax - ymin);
}

TopoDS_Wire polygon_wire(const Ring& ring, double z) {
  BRepBuilderAPI_MakePolygon polygon;
  for (const Point2& p : ring) polygon.Add(gp_Pnt(p.x, p.y, z));
  polygon.Close();
  return polygon.Wire();
}

}  // namespace

std::string surface_name(const TopoDS_Face& face) {
  return surface_type_name(BRepAdaptor_Surface(face, false).GetType());
}

bool planar_face_normal(const TopoDS_Face& face, gp_Dir* normal) {
  gp_Pln plane;
  if (face.IsNull() || !plane_of(face, &plane)) return false;
  *normal = plane.Axis().Direction();
  if (face.Orientation() == TopAbs_REVERSED) normal->Reverse();
  return true;
}

FaceRings read_face_rings(const TopoDS_Face& face) {
  if (face.IsNull()) throw InputError("the face is empty (a null shape)");
  const gp_Pln plane = face_plane(face);
  gp_Dir normal = plane.Axis().Direction();
  if (face.Orientation() == TopAbs_REVERSED) normal.Reverse();
  if (std::fabs(normal.Z()) < 1.0 - 1e-9) {
    constexpr double kDirectionTolerance = 1e-9;
    throw InputError("the face lies in a plane with normal (" + format_number(normal.X(), kDirectionTolerance) + ", " +
                     format_number(normal.Y(), kDirectionTolerance) + ", " +
                     format_number(normal.Z(), kDirectionTolerance) + "), not parallel to the XY plane of its frame");
  }
  FaceRings result;
  result.normal_up = normal.Z() > 0;
  result.z = plane.Location().Z();
  result.approximate = BRepAdaptor_Surface(face, false).GetType() != GeomAbs_Plane;

  const double face_size = face_box_size(face);
  const double tol = tolerance_for_size(face_size);
  const TopoDS_Wire outer = BRepTools::OuterWire(face);
  int inner_count = 0;
  for (TopExp_Explorer wires(face, TopAbs_WIRE); wires.More(); wires.Next()) {
    const TopoDS_Wire wire = TopoDS::Wire(wires.Current());
    std::vector<FaceRings::Edge> entries;
    RawRing ring;
    ring.name = wire.IsSame(outer) ? "outer wire" : "inner wire " + std::to_string(++inner_count);
    int edge_count = 0;
    for (TopExp_Explorer edges(wire, TopAbs_EDGE); edges.More(); edges.Next()) {
      if (!BRep_Tool::Degenerated(TopoDS::Edge(edges.Current()))) ++edge_count;
    }
    int walked = 0;
    for (BRepTools_WireExplorer walk(wire, face); walk.More(); walk.Next()) {
      const TopoDS_Edge& edge = walk.Current();
      if (BRep_Tool::Degenerated(edge)) continue;
      ++walked;
      const gp_Pnt start = BRep_Tool::Pnt(walk.CurrentVertex());
      const double start_tolerance = BRep_Tool::Tolerance(walk.CurrentVertex());
      const EdgeCurve curve = edge_curve(edge, face_size);
      result.approximate = result.approximate || curve.recognised();
      if (curve.shape == EdgeShape::Circle) {
        // A circular arc (stored as a circle, or a B-spline or Bezier curve that is one: edge_curve.h):
        // its samples (all but the last, the next edge's start) and the arc itself.
        CircularArc arc;
        arc.center = Point2{curve.circle.Location().X(), curve.circle.Location().Y()};
        arc.radius = curve.circle.Radius();
        arc.start = std::atan2(start.Y() - arc.center.y, start.X() - arc.center.x);
        arc.sweep = circle_edge_sweep(edge, curve.circle);
        // The face lies on the left of its edges run in wire order (seen from its normal's side):
        // inside the circle when the arc runs counter-clockwise around it, seen so.
        arc.outside = (arc.sweep > 0) != result.normal_up;
        // (Its samples are added below, once the face's size says whether it is a short arc.)
        entries.push_back({Point2{start.X(), start.Y()}, static_cast<int>(result.arcs.size()), start.Z(), start_tolerance});
        result.arcs.push_back(arc);
        continue;
      }
      if (curve.shape != EdgeShape::Line) {
        TopoDS_Vertex v1, v2;
        TopExp::Vertices(edge, v1, v2, true);
        const gp_Pnt a = BRep_Tool::Pnt(v1), b = BRep_Tool::Pnt(v2);
        std::string what = with_article(curve_type_name(curve.stored));
        if (curve.tolerance > 0) {
          what += " that is neither a straight line nor a circular arc within its tolerance " + format_significant(curve.tolerance, 2) +
                  " (it strays " + format_significant(curve.deviation, 2) + " from the nearest)";
        }
        throw InputError("edge " + std::to_string(walked) + " of the " + ring.name + ", from " +
                         format_point(a.X(), a.Y(), tol) + " to " + format_point(b.X(), b.Y(), tol) + ", is " + what +
                         "; only straight edges and circular arcs are supported");
      }
      entries.push_back({Point2{start.X(), start.Y()}, -1, start.Z(), start_tolerance});
    }
    if (walked != edge_count || !BRep_Tool::IsClosed(wire)) {
      throw InputError("the " + ring.name + " is not a closed chain of edges");
    }
    result.rings.push_back(std::move(ring));
    result.edges.push_back(std::move(entries));
  }
  // The face's size: the longer side of the box of its vertices and its arcs' default samples.
  double xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300;
  auto extend = [&](Point2 p) {
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x), ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  };
  for (const std::vector<FaceRings::Edge>& loop : result.edges) {
    for (const FaceRings::Edge& e : loop) extend(e.start);
  }
  for (const CircularArc& arc : result.arcs) {
    for (const Point2& p : polygonise_arc(arc)) extend(p);
  }
  const double box_size = std::max(xmax - xmin, ymax - ymin);
  for (CircularArc& arc : result.arcs) {
    if (short_arc(arc, box_size)) arc.chords = 1;
  }
  // The loops: each straight edge's start; each arc's start and its polygon's inner points.
  for (size_t w = 0; w < result.edges.size(); ++w) {
    for (const FaceRings::Edge& e : result.edges[w]) {
      result.rings[w].points.push_back(e.start);
      if (e.arc < 0) continue;
      const std::vector<Point2> polygon = polygonise_arc(result.arcs[static_cast<size_t>(e.arc)]);
      for (size_t k = 1; k + 1 < polygon.size(); ++k) result.rings[w].points.push_back(polygon[k]);
    }
  }
  return result;
}

TopoDS_Face face_from_rings(const FaceRings& rings) {
  const gp_Pln plane(gp_Pnt(0, 0, rings.z), gp_Dir(0, 0, rings.normal_up ? 1 : -1));
  std::vector<TopoDS_Wire> wires;
  for (const std::vector<FaceRings::Edge>& loop : rings.edges) {
    std::vector<TopoDS_Vertex> vertices;
    for (const FaceRings::Edge& e : loop) vertices.push_back(BRepBuilderAPI_MakeVertex(gp_Pnt(e.start.x, e.start.y, rings.z)));
    BRepBuilderAPI_MakeWire wire;
    for (size_t k = 0; k < loop.size(); ++k) {
      const TopoDS_Vertex &a = vertices[k], &b = vertices[(k + 1) % loop.size()];
      if (loop[k].arc < 0) {
        wire.Add(BRepBuilderAPI_MakeEdge(a, b).Edge());
        continue;
      }
      const CircularArc& arc = rings.arcs[static_cast<size_t>(loop[k].arc)];
      const gp_Circ circle(gp_Ax2(gp_Pnt(arc.center.x, arc.center.y, rings.z), gp_Dir(0, 0, arc.sweep > 0 ? 1 : -1), gp_Dir(1, 0, 0)), arc.radius);
      Handle(Geom_Circle) curve = new Geom_Circle(circle);
      // Its parameter is the angle from +X about its axis (+Z when it runs counter-clockwise, else -Z):
      // from the start as read, turning by |sweep|.
      const double from = arc.sweep > 0 ? arc.start : -arc.start;
      BRepBuilderAPI_MakeEdge edge(curve, a, b, from, from + std::fabs(arc.sweep));
      if (!edge.IsDone()) throw InputError("OpenCASCADE cannot make the face's arc about " + format_point(arc.center.x, arc.center.y) + " again");
      wire.Add(edge.Edge());
    }
    if (!wire.IsDone()) throw InputError("OpenCASCADE cannot make the face's wires again");
    wires.push_back(wire.Wire());
  }
  if (wires.empty()) throw InputError("the face has no wire");
  BRepBuilderAPI_MakeFace make(plane, wires[0], true);
  for (size_t k = 1; k < wires.size(); ++k) make.Add(wires[k]);
  if (!make.IsDone()) throw InputError("OpenCASCADE cannot make the face again from its edges");
  return make.Face();
}

void check_vertices_on_plane(const FaceRings& rings, double tolerance) {
  for (const std::vector<FaceRings::Edge>& loop : rings.edges) {
    for (const FaceRings::Edge& e : loop) {
      if (std::fabs(e.z - rings.z) > std::max({tolerance, 1e-7, e.tolerance})) {
        throw InputError("a vertex of the face lies off its plane z = " + format_number(rings.z, tolerance) + " by " +
                         format_significant(std::fabs(e.z - rings.z), 2));
      }
    }
  }
}

bool rings_rectilinear(const std::vector<RawRing>& rings) {
  const double tol = face_tolerance(rings);
  for (const RawRing& ring : rings) {
    const size_t n = ring.points.size();
    for (size_t i = 0; i < n; ++i) {
      const Point2 a = ring.points[i], b = ring.points[(i + 1) % n];
      if (!(std::fabs(b.x - a.x) <= tol || std::fabs(b.y - a.y) <= tol)) return false;
    }
  }
  return true;
}

PlanarFace planar_face_from_occt(const TopoDS_Face& face) {
  const FaceRings read = read_face_rings(face);
  PlanarFace result;
  result.normal_up = read.normal_up;
  result.z = read.z;
  result.polygon = validate_rings(read.rings, &result.tolerance);
  check_vertices_on_plane(read, result.tolerance);
  return result;
}

Placement face_frame(const TopoDS_Face& face) {
  gp_Dir normal;
  if (!planar_face_normal(face, &normal)) return Placement{};
  struct Line {
    gp_Pnt a, b;
  };
  std::vector<Line> lines;
  const double face_size = face_box_size(face);
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    if (BRep_Tool::Degenerated(edge) || edge_curve(edge, face_size).shape != EdgeShape::Line) continue;
    TopoDS_Vertex v1, v2;
    TopExp::Vertices(edge, v1, v2, true);
    if (v1.IsNull() || v2.IsNull()) continue;
    const gp_Pnt a = BRep_Tool::Pnt(v1), b = BRep_Tool::Pnt(v2);
    if (a.Distance(b) > 0) lines.push_back(Line{a, b});
  }
  const bool parallel_to_xy = std::fabs(normal.Z()) >= 1.0 - 1e-9;
  if (lines.empty()) {
    // No straight edge (a disk, a washer, a face bounded by arcs alone): in the XY plane it keeps the
    // model's coordinates; in a tilted plane, origin at its first vertex (else the plane's origin), X
    // along the plane's own X direction.
    if (parallel_to_xy) return Placement{};
    gp_Pln plane;
    if (!plane_of(face, &plane)) return Placement{};
    gp_Pnt origin = plane.Location();
    TopExp_Explorer vertex(face, TopAbs_VERTEX);
    if (vertex.More()) origin = BRep_Tool::Pnt(TopoDS::Vertex(vertex.Current()));
    gp_Vec u(plane.Position().XDirection());
    u -= gp_Vec(normal) * u.Dot(gp_Vec(normal));
    if (u.Magnitude() <= 1e-12) return Placement{};
    const gp_Dir x(u);
    const gp_Dir y = normal.Crossed(x);
    Placement frame;
    frame.rotation = {x.X(), y.X(), normal.X(), x.Y(), y.Y(), normal.Y(), x.Z(), y.Z(), normal.Z()};
    frame.translation = {origin.X(), origin.Y(), origin.Z()};
    return frame;
  }
  const double tol = tolerance_for_size(face_size);
  if (parallel_to_xy) {
    for (const Line& l : lines) {
      if (std::fabs(l.b.X() - l.a.X()) <= tol || std::fabs(l.b.Y() - l.a.Y()) <= tol) return Placement{};
    }
  }
  const Line& longest = *std::max_element(lines.begin(), lines.end(), [](const Line& p, const Line& q) {
    return p.a.SquareDistance(p.b) < q.a.SquareDistance(q.b);
  });
  gp_Vec u(longest.a, longest.b);
  u -= gp_Vec(normal) * u.Dot(gp_Vec(normal));
  if (u.Magnitude() <= 0) return Placement{};
  const gp_Dir x(u);
  const gp_Dir y = normal.Crossed(x);
  if (parallel_to_xy) {
    // A face in the XY plane keeps the model's coordinates unless it is rectilinear in the turned frame.
    for (const Line& l : lines) {
      const gp_Vec d(l.a, l.b);
      if (!(std::fabs(d.Dot(gp_Vec(x))) <= tol || std::fabs(d.Dot(gp_Vec(y))) <= tol)) return Placement{};
    }
  }
  Placement frame;
  frame.rotation = {x.X(), y.X(), normal.X(), x.Y(), y.Y(), normal.Y(), x.Z(), y.Z(), normal.Z()};
  frame.translation = {longest.a.X(), longest.a.Y(), longest.a.Z()};
  return frame;
}

TopoDS_Shape shape_to_model(const TopoDS_Shape& shape, const Placement& frame) {
  if (frame.identity()) return shape;
  BRepBuilderAPI_Transform move(shape, frame.to_model(), true);
  if (!move.IsDone()) throw std::runtime_error("OpenCASCADE could not carry a shape back into the model");
  if (occt_shape_valid(move.Shape()) || !occt_shape_valid(shape)) return move.Shape();
  // Copying the geometry through the rotation can leave an edge whose tolerance no longer covers
  // its vertices (a general face's cut ends lie a lattice step apart): the shape moved by a
  // location instead keeps its geometry, and so its validity.
  return shape.Moved(TopLoc_Location(frame.to_model()));
}

TopoDS_Face occt_face_from_polygon(const RectilinearPolygon& polygon, double z, bool normal_up) {
  const gp_Pln plane(gp_Pnt(0, 0, z), gp_Dir(0, 0, 1));
  BRepBuilderAPI_MakeFace maker(plane, polygon_wire(polygon.outer, z), true);
  for (const Ring& hole : polygon.holes) maker.Add(polygon_wire(hole, z));
  TopoDS_Face face = maker.Face();
  if (!normal_up) face.Reverse();
  return face;
}

TopoDS_Face occt_rectangle(const Box& box, double z, bool normal_up) {
  RectilinearPolygon polygon;
  polygon.outer = {{box.xmin, box.ymin}, {box.xmax, box.ymin}, {box.xmax, box.ymax}, {box.xmin, box.ymax}};
  return occt_face_from_polygon(polygon, z, normal_up);
}

}  // namespace autoblock
