#include "core/mesh/mesh_conformity.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/common/format.h"

namespace autoblock {
namespace {

struct Segment {
  Point2 a, b;
};

// True when p lies on segment s (axis-parallel) within tolerance.
bool on_segment(const Point2& p, const Segment& s, double tolerance) {
  const double x0 = std::min(s.a.x, s.b.x), x1 = std::max(s.a.x, s.b.x);
  const double y0 = std::min(s.a.y, s.b.y), y1 = std::max(s.a.y, s.b.y);
  return p.x >= x0 - tolerance && p.x <= x1 + tolerance && p.y >= y0 - tolerance && p.y <= y1 + tolerance;
}

}  // namespace

Conformity check_conformity(const QuadMesh& mesh, const RectilinearPolygon& face) {
  Conformity c;
  std::vector<Segment> rings;
  auto add_ring = [&](const Ring& ring) {
    for (size_t k = 0; k < ring.size(); ++k) {
      const Segment s{ring[k], ring[(k + 1) % ring.size()]};
      c.face_perimeter += std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
      rings.push_back(s);
    }
  };
  add_ring(face.outer);
  for (const Ring& hole : face.holes) add_ring(hole);
  c.face_area = polygon_area(face);
  const Box box = ring_bbox(face.outer);
  const double tolerance = 1e-9 * box.longer_side();

  for (size_t q = 0; q < mesh.quads.size(); ++q) {
    const auto p = mesh.corners(q);
    double twice = 0;
    for (size_t k = 0; k < 4; ++k) twice += p[k].x * p[(k + 1) % 4].y - p[(k + 1) % 4].x * p[k].y;
    c.quad_area += 0.5 * twice;
    c.inverted_quads += twice <= 0;
  }
  for (const MeshEdge& e : mesh_edges(mesh)) {
    if (e.uses == 2) {
      ++c.interior_edges;
      c.misoriented_edges += e.forward != 1;
    } else if (e.uses > 2) {
      ++c.overused_edges;
    } else {
      ++c.boundary_edges;
      const Point2& a = mesh.nodes[static_cast<size_t>(e.a)];
      const Point2& b = mesh.nodes[static_cast<size_t>(e.b)];
      c.boundary_length += std::hypot(b.x - a.x, b.y - a.y);
      const bool on_boundary = std::any_of(rings.begin(), rings.end(), [&](const Segment& s) {
        return on_segment(a, s, tolerance) && on_segment(b, s, tolerance);
      });
      c.stray_boundary_edges += !on_boundary;
    }
  }
  const double area_tolerance = 1e-9 * std::max(c.face_area, 1e-300);
  const double length_tolerance = 1e-9 * c.face_perimeter;
  if (mesh.quads.empty()) c.problem = "the mesh has no quads";
  else if (c.overused_edges) c.problem = counted(c.overused_edges, "edge") + (c.overused_edges == 1 ? " is" : " are") + " used by more than two quads";
  else if (c.stray_boundary_edges) c.problem = counted(c.stray_boundary_edges, "edge") + " inside the face " + (c.stray_boundary_edges == 1 ? "belongs" : "belong") + " to one quad only (hanging nodes or unshared edges)";
  else if (c.misoriented_edges) c.problem = counted(c.misoriented_edges, "interior edge") + (c.misoriented_edges == 1 ? " is" : " are") + " run the same way by both their quads (inconsistent orientation)";
  else if (c.inverted_quads) c.problem = counted(c.inverted_quads, "quad") + (c.inverted_quads == 1 ? " is" : " are") + " inverted or degenerate";
  else if (std::fabs(c.quad_area - c.face_area) > area_tolerance) c.problem = "the quads' area differs from the face's";
  else if (std::fabs(c.boundary_length - c.face_perimeter) > length_tolerance) c.problem = "the mesh boundary does not cover the face's boundary";
  c.conformal = c.problem.empty();
  return c;
}

}  // namespace autoblock
