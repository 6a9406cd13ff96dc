// An independent check that a hexahedral mesh is conformal and fills its solid exactly.
//
// Uses nothing but the hexahedra and the solid's figures (volume, surface area, each face's area):
// every quad face of a hexahedron is used by one or two hexahedra (none by three); every face used by
// two is run once each way (consistent orientation); no hexahedron is inverted (a corner Jacobian
// <= 0 or a volume <= 0, hex_quality.h); the faces used once (the boundary) have the solid's surface
// area, and the hexahedra's volumes add up to the solid's. A hanging node or an unshared face shows up
// as boundary area beyond the solid's. Then the mesh's own boundary list (HexMesh::boundary, the
// quads tagged with the solid's faces) is checked against it: the same quads, and on every face of the
// solid quads whose areas add up to the face's.
#pragma once

#include <string>
#include <vector>

#include "core/mesh/hex_mesh.h"

namespace autoblock {

struct HexConformity {
  bool conformal = false;
  int interior_faces = 0;     // used by two hexahedra
  int boundary_faces = 0;     // used by one
  int overused_faces = 0;     // used by three or more
  int misoriented_faces = 0;  // used by two running it the same way
  int inverted_hexes = 0;
  int mismatched_faces = 0;   // faces of the solid whose tagged quads' area is not the face's
  double hex_volume = 0.0, solid_volume = 0.0;
  double boundary_area = 0.0, solid_area = 0.0;
  std::string problem;        // why it is not conformal ("" when it is)
};

// What the mesh must fill: the solid's figures.
struct SolidFigures {
  double volume = 0.0, area = 0.0;
  std::vector<double> face_areas;       // [k - 1]: the area of the solid's face k (0: no face of the solid)
  std::vector<double> face_perimeters;  // [k - 1]: its perimeter (empty: all 0)
  double tolerance = 0.0;               // how far a node may lie off the solid's boundary (a general
                                        // face's nodes lie on its lattice: within its quantum)
};

// Inputs:  mesh; solid.
// Output:  the figures above and the verdict: volumes agree within 1e-9 relative plus tolerance times
//          the solid's area, areas within 1e-9 relative plus tolerance times the perimeters (all
//          faces', or the face's).
HexConformity check_hex_conformity(const HexMesh& mesh, const SolidFigures& solid);

// Inputs: corners of a quad (planar, or nearly). Output: its area vector (half the cross product of
// its diagonals): normal to it, as long as its area.
Point3 quad_area_vector(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

// Inputs: corners of a hexahedron (planar faces). Output: its volume (divergence theorem over its faces).
double hex_volume(const std::array<Point3, 8>& corners);

}  // namespace autoblock
