#include "core/mesh/mesh_conformity.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/common/format.h"
#include "core/mesh/mesh_quality.h"
#include "core/region/region.h"

namespace autoblock {
namespace {

struct Segment {
  Point2 a, b;
};

}  // namespace

Conformity check_conformity(const QuadMesh& mesh, const RectilinearPolygon& face) {
  std::vector<Ring> loops{face.outer};
  loops.insert(loops.end(), face.holes.begin(), face.holes.end());
  return check_conformity(mesh, loops, 1e-9 * ring_bbox(face.outer).longer_side());
}

Conformity check_conformity(const QuadMesh& mesh, const std::vector<Ring>& loops, double tolerance) {
  return check_conformity(mesh, loops, tolerance, FaceArcs{});
}

Conformity check_conformity(const QuadMesh& mesh, const std::vector<Ring>& loops, double tolerance, const FaceArcs& arcs) {
  Conformity c;
  std::vector<Segment> rings;
  for (size_t l = 0; l < loops.size(); ++l) {
    // The outer loop adds its area, holes take theirs away, whatever their orientation; the region
    // lies on the left of a loop run so.
    const double area = signed_area(loops[l]);
    const bool reversed = (l == 0) != (area > 0);
    Ring ring = loops[l];
    if (reversed) std::reverse(ring.begin(), ring.end());
    for (size_t k = 0; k < ring.size(); ++k) {
      const Segment s{ring[k], ring[(k + 1) % ring.size()]};
      const int arc = arcs.arc_of_chord(s.a, s.b);
      if (arc < 0) {
        c.face_perimeter += std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
        rings.push_back(s);
        continue;
      }
      // A chord of an arc: the face has the arc (and the segment between them) instead.
      const ArcGap gap = arc_gap(arcs.arcs[static_cast<size_t>(arc)], s.a, s.b);
      c.face_perimeter += gap.arc_length;
      c.face_area += gap.area;
    }
    c.face_area += (l == 0 ? 1.0 : -1.0) * std::fabs(area);
  }
  for (size_t q = 0; q < mesh.quads.size(); ++q) {
    const auto p = mesh.corners(q);
    double twice = 0;
    for (size_t k = 0; k < 4; ++k) twice += p[k].x * p[(k + 1) % 4].y - p[(k + 1) % 4].x * p[k].y;
    c.quad_area += 0.5 * twice;
    // Inverted: a corner whose edges turn clockwise or run straight (a Jacobian <= 0 there), or no area.
    if (twice <= 0 || quad_scaled_jacobian(p) <= 0.0) {
      if (c.inverted_quads++ == 0) {
        c.first_inverted = Point2{0.25 * (p[0].x + p[1].x + p[2].x + p[3].x), 0.25 * (p[0].y + p[1].y + p[2].y + p[3].y)};
      }
    }
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
      const int arc = arcs.arc_of_mesh_edge(a, b);
      if (arc >= 0) {
        // Run as its quad runs it (the mesh on its left): the quads miss the gap to the arc.
        const ArcGap gap = e.forward == 1 ? arc_gap(arcs.arcs[static_cast<size_t>(arc)], a, b)
                                          : arc_gap(arcs.arcs[static_cast<size_t>(arc)], b, a);
        c.boundary_length += gap.arc_length;
        c.curved_gap_area += gap.area;
        continue;
      }
      c.boundary_length += std::hypot(b.x - a.x, b.y - a.y);
      const bool on_boundary = std::any_of(rings.begin(), rings.end(), [&](const Segment& s) {
        return segment_distance(a, s.a, s.b) <= tolerance && segment_distance(b, s.a, s.b) <= tolerance;
      });
      c.stray_boundary_edges += !on_boundary;
    }
  }
  const double area_tolerance = 1e-9 * std::max(c.face_area, 1e-300) + tolerance * c.face_perimeter;
  const double length_tolerance = 1e-9 * c.face_perimeter + 2.0 * tolerance * c.boundary_edges;
  if (mesh.quads.empty()) c.problem = "the mesh has no quads";
  else if (c.overused_edges) c.problem = counted(c.overused_edges, "edge") + (c.overused_edges == 1 ? " is" : " are") + " used by more than two quads";
  else if (c.stray_boundary_edges) c.problem = counted(c.stray_boundary_edges, "edge") + " inside the face " + (c.stray_boundary_edges == 1 ? "belongs" : "belong") + " to one quad only (hanging nodes or unshared edges)";
  else if (c.misoriented_edges) c.problem = counted(c.misoriented_edges, "interior edge") + (c.misoriented_edges == 1 ? " is" : " are") + " run the same way by both their quads (inconsistent orientation)";
  else if (c.inverted_quads) {
    std::ostringstream at;
    at.precision(6);
    at << " (the first near " << c.first_inverted.x << ", " << c.first_inverted.y << ")";
    c.problem = counted(c.inverted_quads, "quad") + (c.inverted_quads == 1 ? " is" : " are") + " inverted or degenerate" + at.str();
  }
  else if (std::fabs(c.quad_area + c.curved_gap_area - c.face_area) > area_tolerance) c.problem = "the quads' area differs from the face's";
  else if (std::fabs(c.boundary_length - c.face_perimeter) > length_tolerance) c.problem = "the mesh boundary does not cover the face's boundary";
  c.conformal = c.problem.empty();
  return c;
}

}  // namespace autoblock
