// A mesh judged against the true face (lines and circles as OpenCASCADE holds them, in the model's
// coordinates), the same way for every mesher: the benchmarks' check on faces with circular arcs.
//
// Inputs:  mesh, quads in the model's coordinates (the face lies in z = 0); face, the face it meshes;
//          tolerance, how far a boundary node may lie off the face's boundary and be on it.
// Outputs: CurvedConformity: every boundary node's distance to the face's edges (the largest, how many
//          lie farther than tolerance, how many lie on a circle and the largest distance among those); every boundary edge of the mesh (one
//          quad) on one edge of the face (a chord of a circle edge: both ends on the arc, its middle's
//          direction within the arc); no edge used by three quads, every interior edge run both ways,
//          no inverted quad; the quads' area plus the circular segments between the boundary chords and
//          their arcs equal to the face's area (relative 1e-6) and the boundary's arc and segment lengths
//          equal to its perimeter (relative 1e-6). problem says the first failure ("" when conformal).
#pragma once

#include <BRepAdaptor_Curve.hxx>
#include <BRepGProp.hxx>
#include <ElCLib.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/geometry/circular_arc.h"
#include "core/geometry/rectilinear_polygon.h"
#include "core/mesh/mesh_quality.h"
#include "core/mesh/quad_mesh.h"

namespace autoblock::bench {

struct CurvedConformity {
  bool conformal = false;
  std::string problem;
  int boundary_nodes = 0, nodes_on_circles = 0, nodes_off = 0;
  double worst_off = 0.0;  // the largest distance of a boundary node from the face's boundary
  double worst_off_circles = 0.0;  // the same over the nodes nearest a circle edge
  int stray_edges = 0, overused_edges = 0, misoriented_edges = 0, inverted_quads = 0;
  double quad_area = 0.0, gap_area = 0.0, face_area = 0.0, boundary_length = 0.0, perimeter = 0.0;
};

namespace detail {

struct TrueEdge {
  bool circle = false;
  gp_Pnt a, b;          // a line's ends; a circle's first and last points
  gp_Circ circ;
  double first = 0, last = 0;

  // The parameter of p's direction on the circle, or -1 when it lies outside [first, last].
  double circle_parameter(const gp_Pnt& p) const {
    double u = ElCLib::Parameter(circ, p);
    while (u < first - 1e-12) u += 2.0 * M_PI;
    while (u > first + 2.0 * M_PI) u -= 2.0 * M_PI;
    return u <= last + 1e-12 ? u : -1.0;
  }
  double distance(const gp_Pnt& p) const {
    if (circle) {
      if (circle_parameter(p) >= 0.0) return std::fabs(p.Distance(circ.Location()) - circ.Radius());
      return std::min(p.Distance(a), p.Distance(b));
    }
    const gp_Vec ab(a, b), ap(a, p);
    const double t = std::clamp(ap.Dot(ab) / std::max(ab.SquareMagnitude(), 1e-300), 0.0, 1.0);
    return p.Distance(a.Translated(t * ab));
  }
};

}  // namespace detail

inline CurvedConformity check_curved_conformity(const QuadMesh& mesh, const TopoDS_Face& face, double tolerance) {
  CurvedConformity c;
  std::vector<detail::TrueEdge> edges;
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(face, TopAbs_EDGE, map);
  for (int k = 1; k <= map.Extent(); ++k) {
    const BRepAdaptor_Curve curve(TopoDS::Edge(map(k)));
    detail::TrueEdge e;
    e.first = curve.FirstParameter();
    e.last = curve.LastParameter();
    e.a = curve.Value(e.first);
    e.b = curve.Value(e.last);
    e.circle = curve.GetType() == GeomAbs_Circle;
    if (e.circle) e.circ = curve.Circle();
    edges.push_back(e);
  }
  GProp_GProps surface, lines;
  BRepGProp::SurfaceProperties(face, surface);
  BRepGProp::LinearProperties(face, lines);
  c.face_area = std::fabs(surface.Mass());
  c.perimeter = lines.Mass();
  auto point = [&](int v) { return gp_Pnt(mesh.nodes[static_cast<size_t>(v)].x, mesh.nodes[static_cast<size_t>(v)].y, 0.0); };
  for (size_t q = 0; q < mesh.quads.size(); ++q) {
    const auto corners = mesh.corners(q);
    const double area = signed_area(Ring(corners.begin(), corners.end()));
    c.quad_area += area;
    c.inverted_quads += area <= 0 || quad_scaled_jacobian(corners) <= 0.0;
  }
  std::vector<char> boundary(mesh.nodes.size(), 0);
  for (const MeshEdge& m : mesh_edges(mesh)) {
    if (m.uses == 2) {
      c.misoriented_edges += m.forward != 1;
      continue;
    }
    if (m.uses > 2) {
      ++c.overused_edges;
      continue;
    }
    boundary[static_cast<size_t>(m.a)] = boundary[static_cast<size_t>(m.b)] = 1;
    // Run as its quad runs it, the mesh on its left.
    const int from = m.forward == 1 ? m.a : m.b, to = m.forward == 1 ? m.b : m.a;
    const gp_Pnt a = point(from), b = point(to);
    const gp_Pnt middle((a.X() + b.X()) / 2, (a.Y() + b.Y()) / 2, 0.0);
    const detail::TrueEdge* on = nullptr;
    for (const detail::TrueEdge& e : edges) {
      if (e.distance(a) > tolerance || e.distance(b) > tolerance) continue;
      // A chord of an arc: its middle's direction within the arc (not across the rest of the circle).
      if (e.circle && e.circle_parameter(middle) < 0.0) continue;
      if (!e.circle && e.distance(middle) > tolerance) continue;
      on = &e;
      break;
    }
    if (!on) {
      ++c.stray_edges;
      continue;
    }
    if (on->circle) {
      CircularArc arc;
      arc.center = {on->circ.Location().X(), on->circ.Location().Y()};
      arc.radius = on->circ.Radius();
      const ArcGap gap = arc_gap(arc, Point2{a.X(), a.Y()}, Point2{b.X(), b.Y()});
      c.boundary_length += gap.arc_length;
      c.gap_area += gap.area;
    } else {
      c.boundary_length += a.Distance(b);
    }
  }
  for (size_t v = 0; v < boundary.size(); ++v) {
    if (!boundary[v]) continue;
    ++c.boundary_nodes;
    double nearest = 1e300;
    bool circle = false;
    for (const detail::TrueEdge& e : edges) {
      const double d = e.distance(point(static_cast<int>(v)));
      if (d < nearest) {
        nearest = d;
        circle = e.circle;
      }
    }
    c.worst_off = std::max(c.worst_off, nearest);
    c.nodes_off += nearest > tolerance;
    c.nodes_on_circles += circle && nearest <= tolerance;
    if (circle) c.worst_off_circles = std::max(c.worst_off_circles, nearest);
  }
  if (mesh.quads.empty()) c.problem = "no quads";
  else if (c.overused_edges) c.problem = std::to_string(c.overused_edges) + " edges used by three or more quads";
  else if (c.nodes_off) c.problem = std::to_string(c.nodes_off) + " boundary nodes off the face's boundary";
  else if (c.stray_edges) c.problem = std::to_string(c.stray_edges) + " boundary edges not on one edge of the face";
  else if (c.misoriented_edges) c.problem = std::to_string(c.misoriented_edges) + " interior edges run one way by both quads";
  else if (c.inverted_quads) c.problem = std::to_string(c.inverted_quads) + " inverted quads";
  else if (std::fabs(c.quad_area + c.gap_area - c.face_area) > 1e-6 * c.face_area) c.problem = "the quads' area and the gaps differ from the face's";
  else if (std::fabs(c.boundary_length - c.perimeter) > 1e-6 * c.perimeter) c.problem = "the mesh boundary does not cover the face's boundary";
  c.conformal = c.problem.empty();
  return c;
}

}  // namespace autoblock::bench
