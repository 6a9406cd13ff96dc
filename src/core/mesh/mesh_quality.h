// Element quality of quadrilateral meshes and the regularity of their nodes.
//
// Per quad (corners p0..p3 counter-clockwise):
//   scaled Jacobian  min over the corners of (e1 x e2) / (|e1| |e2|), e1 and e2 the edges leaving
//                    the corner in counter-clockwise order: 1 for a rectangle, <= 0 when inverted;
//   aspect ratio     longest edge over shortest edge: 1 for a square;
//   skew             |cos| of the angle between the principal axes (p1 - p0 + p2 - p3 and
//                    p3 - p0 + p2 - p1): 0 for a rectangle (Verdict's definition);
//   min/max angle    interior angles in degrees: 90 and 90 for a rectangle.
// An interior node is irregular when its valence (number of quads around it) is not 4; boundary
// nodes are the ends of edges used by one quad only.
#pragma once

#include <array>

#include "core/mesh/quad_mesh.h"

namespace autoblock {

struct QuadQuality {
  double scaled_jacobian = 0.0, aspect_ratio = 0.0, skew = 0.0, min_angle = 0.0, max_angle = 0.0;
};

struct MeshQuality {
  double min_scaled_jacobian = 0.0, mean_scaled_jacobian = 0.0;
  double max_aspect_ratio = 0.0, mean_aspect_ratio = 0.0;
  double max_skew = 0.0;
  double min_angle = 0.0, max_angle = 0.0;  // over all quads, degrees
  int interior_nodes = 0;
  int irregular_interior_nodes = 0;         // interior nodes whose valence is not 4
};

// Inputs: the four corners, counter-clockwise. Output: the measures above.
QuadQuality quad_quality(const std::array<Point2, 4>& corners);

// Inputs: the four corners, counter-clockwise. Output: the scaled Jacobian alone (quad_quality's):
// <= 0 when a corner is reflex or flat, or an edge has no length.
double quad_scaled_jacobian(const std::array<Point2, 4>& corners);

// Inputs: the four corners. Output: the aspect ratio alone (quad_quality's): the longest edge over the
// shortest, infinite when an edge has no length.
double quad_edge_ratio(const std::array<Point2, 4>& corners);

// Inputs: mesh with at least one quad. Output: the statistics over all quads and nodes.
MeshQuality mesh_quality(const QuadMesh& mesh);

// A quad longer than this (longest edge over shortest) is taken to be degenerate: an edge of next to
// no length, a triangle in all but name, whose corners the scaled Jacobian still scores well (a strip
// of quads 40 000 times longer than wide, from two vertices of the block model a hair apart, scored
// 0.76). A mapped mesh's honest stretch stays well below: gmsh's largest on 200 faces with arcs, 15.3.
constexpr double kDegenerateEdgeRatio = 100.0;

// Inputs: quality, of a mesh. Output: its minimum scaled Jacobian as meshes of one face are judged by
//         it: as it is where every quad is valid (> 0) and none degenerate (kDegenerateEdgeRatio);
//         1 less with a degenerate quad, 2 less with an invalid one; so that any mesh of the first
//         kind ranks above any of the second, and those above any of the third.
double judged_jacobian(const MeshQuality& quality);


}  // namespace autoblock
