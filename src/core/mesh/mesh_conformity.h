// An independent check that a quad mesh is conformal and covers its face exactly.
//
// Uses nothing but the mesh and the face's polygon: every mesh edge is used by one or two quads;
// every edge used once (a boundary edge) lies on the face's boundary, and together they are as
// long as the face's perimeter (outer boundary and holes); every interior edge is run once in each
// direction by its two quads (consistent orientation); every quad is counter-clockwise and
// convex (a positive Jacobian at each corner: a reflex corner counts as inverted), and the quads'
// areas add up to the face's. A hanging node or an unshared edge
// shows up as a boundary edge inside the face.
#pragma once

#include <string>

#include "core/geometry/circular_arc.h"
#include "core/geometry/rectilinear_polygon.h"
#include "core/mesh/quad_mesh.h"

namespace autoblock {

struct Conformity {
  bool conformal = false;
  int interior_edges = 0;        // used by two quads
  int boundary_edges = 0;        // used by one quad
  int overused_edges = 0;        // used by three or more quads
  int stray_boundary_edges = 0;  // used by one quad but not on the face's boundary
  int misoriented_edges = 0;     // used by two quads running it the same way
  int inverted_quads = 0;        // a corner with a Jacobian <= 0 (reflex or degenerate), or area <= 0
  Point2 first_inverted;         // the centre of the first inverted quad (named in the problem)
  double quad_area = 0.0, face_area = 0.0;
  // A face with arcs: the area between the mesh's boundary edges on arcs (chords) and the arcs; the
  // quads' area plus this is the face's. It shrinks as the element size does (about h^2 / r per edge).
  double curved_gap_area = 0.0;
  double boundary_length = 0.0, face_perimeter = 0.0;
  std::string problem;           // why it is not conformal ("" when it is)
};

// Inputs: mesh; face, the polygon it should cover. Output: the figures above and the verdict
// (areas and lengths compared to a relative tolerance of 1e-9).
Conformity check_conformity(const QuadMesh& mesh, const RectilinearPolygon& face);

// Inputs: mesh; loops, the face's outer loop and its holes (any orientation, edges at any angle);
//         tolerance, how far a boundary node may lie off the face's boundary (a general face's nodes
//         lie on its lattice: within its quantum).
// Output: the figures above and the verdict: a boundary edge counts as on the boundary when both its
//         ends lie within tolerance of one boundary segment; areas agree within 1e-9 relative plus
//         tolerance times the perimeter, lengths within 1e-9 relative plus twice the tolerance per
//         boundary edge.
Conformity check_conformity(const QuadMesh& mesh, const std::vector<Ring>& loops, double tolerance);

// The same for a face with circular arcs: loops hold the arcs' samples (circular_arc.h), arcs the arcs.
// A loop's chord of an arc counts as the arc (its length and its circular segment in the face's area
// and perimeter); a boundary edge of the mesh whose ends and middle lie on an arc's polygon counts as on
// the boundary, its length as its arc's, and the segment between it and its arc as curved_gap_area:
// the quads' area plus the gap must be the face's, the boundary's arc lengths its perimeter.
Conformity check_conformity(const QuadMesh& mesh, const std::vector<Ring>& loops, double tolerance, const FaceArcs& arcs);

}  // namespace autoblock
