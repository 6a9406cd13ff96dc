// Element quality of hexahedral meshes (Verdict's definitions) and the regularity of their edges.
//
// Per hexahedron (corners 0..7 as in hex_mesh.h):
//   scaled Jacobian  the minimum over the 8 corners of det(e1, e2, e3) / (|e1| |e2| |e3|), e1..e3 the
//                    edges leaving the corner in right-handed order, and of the same at the centre
//                    with the principal axes (Verdict's hex scaled Jacobian): 1 for a box, <= 0 when
//                    inverted, 0 when an edge has no length;
//   aspect ratio     longest edge over shortest edge (Verdict's edge ratio): 1 for a cube;
//   skew             the largest |cos| between two normalised principal axes (Verdict): 0 for a box.
// An edge of the mesh is irregular when the number of hexahedra around it differs from the
// structured one: 4 inside the solid (the hexahedra's angles at the edge add up to 360 degrees); on its
// boundary 2 where the surface is smooth: inside one face of the solid (the mesh's boundary quads on
// both sides of the edge lie on the same face, HexMesh::boundary: a cylinder's chords meet at 165 or
// 195 degrees there) or where the angle is within kSmoothJoin of 180 degrees (a cylinder's tangent
// join with a plane); else, by the solid's dihedral angle there (the hexahedra's angles summed), 1 at a
// convex edge (a box's edge, or an oblique sweep's 60 and 120 degree edges) and 3 at a re-entrant one.
#pragma once

#include <array>
#include <cmath>

#include "core/mesh/hex_mesh.h"

namespace autoblock {

// A boundary edge whose dihedral angle is within this of 180 degrees is smooth (radians): more than
// half the turn of a mesh edge along a convex arc (kMeshEdgeArcSteps chord steps of 15 degrees).
constexpr double kSmoothJoin = 25.0 * M_PI / 180.0;

struct HexQuality {
  double scaled_jacobian = 0.0, aspect_ratio = 0.0, skew = 0.0;
};

struct HexMeshQuality {
  double min_scaled_jacobian = 0.0, mean_scaled_jacobian = 0.0;
  double max_aspect_ratio = 0.0, mean_aspect_ratio = 0.0;
  double max_skew = 0.0;
  int edges = 0, interior_edges = 0;
  int irregular_edges = 0, irregular_interior_edges = 0;
};

// Inputs: the eight corners. Output: the measures above.
HexQuality hex_quality(const std::array<Point3, 8>& corners);

// Inputs: mesh with at least one hexahedron. Output: the statistics over all hexahedra and edges.
HexMeshQuality hex_mesh_quality(const HexMesh& mesh);

}  // namespace autoblock
