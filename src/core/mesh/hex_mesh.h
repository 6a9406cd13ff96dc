// A hexahedral mesh made by sweeping a quad mesh along a vector, layer by layer: nodes, hexahedra,
// the block of every hexahedron, and the mesh's boundary quads with the solid's face they lie on.
//
// Node order of a hexahedron (VTK, Gmsh and Abaqus/CalculiX C3D8 agree): 0-3 one quad, 4-7 the same
// quad one layer on, numbered so that the volume is positive (0-1-2-3 turns right-handed about the
// direction from 0 to 4). Local faces, outward (Abaqus S1..S6 are sides 0..5):
//   0: 0 3 2 1   1: 4 5 6 7   2: 0 1 5 4   3: 1 2 6 5   4: 2 3 7 6   5: 3 0 4 7
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "core/geometry/placement.h"
#include "core/mesh/quad_mesh.h"

namespace autoblock {

using Point3 = std::array<double, 3>;

struct BoundaryQuad {
  int hex = 0;   // 0-based
  int side = 0;  // local face 0..5 (above)
  int face = 0;  // the solid's face it lies on, 1-based
};

struct HexMesh {
  std::vector<Point3> nodes;
  std::vector<std::array<int, 8>> hexes;
  std::vector<int> hex_block;          // per hexahedron: its block, 0-based
  int blocks = 0;
  int layers = 0;
  std::vector<BoundaryQuad> boundary;  // every quad of the mesh's boundary, with its face

  std::array<Point3, 8> corners(size_t hex) const;
};

// Inputs: hex, a hexahedron's nodes; side 0..5. Output: that face's four nodes, outward.
std::array<int, 4> hex_face_nodes(const std::array<int, 8>& hex, int side);

// Inputs:  layers >= 1; grading > 0, the ratio of each layer's thickness to the previous one's
//          (1: uniform).
// Outputs: layers + 1 stations from 0 to 1 (exactly 0 and 1 at the ends), increasing.
// Throws InputError for layers < 1 or a grading that is not a positive finite number.
std::vector<double> layer_stations(int layers, double grading);

// Inputs:  layers >= 1, the layers wanted in all; grading, as above, within each stretch; splits,
//          fractions of the sweep in (0, 1), increasing (SweptSolid::splits), where stations must be.
// Outputs: stations from 0 to 1 with one at every split: each stretch between splits (or an end) gets
//          its share of the layers by its length (largest remainders), at least one, so that there
//          are max(layers, splits + 1) layers; graded within each stretch. No splits: as above.
// Throws InputError as above.
std::vector<double> layer_stations(int layers, double grading, const std::vector<double>& splits);

// Where a swept quad mesh lies and what its boundary is.
struct SweepFrame {
  Placement frame;               // the quad mesh's plane in the model (mesh_export.h's placement)
  Point3 sweep{0, 0, 1};         // model coordinates: the last station's nodes are the first's moved by it
  int bottom_face = 0, top_face = 0;  // the solid's faces at the first and the last station
  std::vector<double> splits;    // fractions of the sweep where the side faces change (SweptSolid::splits)
  // Inputs: the ends of a boundary edge of the quad mesh at the first station (model coordinates);
  //         stretch, which stretch of the sweep between splits (0: from the first station to the first
  //         split, or to the last station when there is none).
  // Output: the solid's face that the edge swept through that stretch lies on.
  std::function<int(const Point3&, const Point3&, int stretch)> side_face;
};

// Inputs:  cap, a quad mesh (counter-clockwise seen from +Z of its plane); where, as above; stations
//          (layer_stations).
// Outputs: the hexahedral mesh: nodes of station k are cap's nodes (through where.frame) plus
//          stations[k] * sweep; one hexahedron per quad and layer, in the quad's block; boundary
//          quads on the caps and on the sides (side_face, by the stretch the layer lies in: stations
//          hold every split, layer_stations).
HexMesh sweep_quad_mesh(const QuadMesh& cap, const SweepFrame& where, const std::vector<double>& stations);

}  // namespace autoblock
