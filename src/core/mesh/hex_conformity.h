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
  double hex_volume = 0.0, solid_volume = 0.0;  // hex_volume: with the segments at cylinder faces (check_hex_conformity)
  double boundary_area = 0.0, solid_area = 0.0;
  std::string problem;        // why it is not conformal ("" when it is)
};

// A face of the solid that is a cylinder (an extruded arc or a drilled hole).
struct FaceCylinder {
  Point3 origin{0, 0, 0}, axis{0, 0, 1};  // a point of its axis; the axis, a unit vector
  double radius = 0.0;                    // 0: the face is no cylinder
  bool convex = true;  // the solid lies inside the circle (a rounded edge), not outside it (a hole)
};

// What the mesh must fill: the solid's figures.
struct SolidFigures {
  double volume = 0.0, area = 0.0;
  std::vector<double> face_areas;       // [k - 1]: the area of the solid's face k (0: no face of the solid)
  std::vector<double> face_perimeters;  // [k - 1]: its perimeter (empty: all 0)
  std::vector<FaceCylinder> face_cylinders;  // [k - 1]: face k's cylinder (empty, or radius 0: planar)
  // With cylinders: the caps (face numbers) and their distance apart. The caps' quads miss (or, at a
  // hole, cover beyond) the segments between their chords and the arcs: the side quads' segments
  // times their heights over this distance.
  int bottom_face = 0, top_face = 0;
  double cap_height = 0.0;
  double tolerance = 0.0;               // how far a node may lie off the solid's boundary (a general
                                        // face's nodes lie on its lattice: within its quantum)
};

// Inputs:  mesh; solid.
// Output:  the figures above and the verdict: volumes agree within 1e-9 relative plus tolerance times
//          the solid's area, areas within 1e-9 relative plus tolerance times the perimeters (all
//          faces', or the face's). A boundary quad on a cylinder face must have its four nodes on the
//          cylinder (within tolerance plus 1e-9 of the radius), two edges along the axis: it is a chord
//          of the cylinder, and it counts as the strip of the cylinder between its nodes (area r * angle
//          * height), the hexahedra's volume as gaining (convex) or losing (a hole) the circular
//          segment between chord and arc times the height.
HexConformity check_hex_conformity(const HexMesh& mesh, const SolidFigures& solid);

// Inputs: corners of a quad (planar, or nearly). Output: its area vector (half the cross product of
// its diagonals): normal to it, as long as its area.
Point3 quad_area_vector(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

// Inputs: corners of a hexahedron (planar faces). Output: its volume (divergence theorem over its faces).
double hex_volume(const std::array<Point3, 8>& corners);

}  // namespace autoblock
