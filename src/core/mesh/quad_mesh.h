// A quadrilateral surface mesh in the plane z = const: nodes, quads and the block of every quad.
#pragma once

#include <array>
#include <vector>

#include "core/geometry/point.h"

namespace autoblock {

struct QuadMesh {
  std::vector<Point2> nodes;              // x, y; the mesh lies in the plane z
  std::vector<std::array<int, 4>> quads;  // node indices, counter-clockwise seen from +Z
  std::vector<int> quad_block;            // per quad: its block, 0-based
  int blocks = 0;                         // number of blocks
  double z = 0.0;

  std::array<Point2, 4> corners(size_t quad) const {
    const auto& q = quads[quad];
    return {nodes[static_cast<size_t>(q[0])], nodes[static_cast<size_t>(q[1])], nodes[static_cast<size_t>(q[2])],
            nodes[static_cast<size_t>(q[3])]};
  }
};

// An edge of a mesh: its nodes (a < b), how many quads use it, and how many of those run from a to
// b (in a consistently oriented mesh an interior edge runs once each way).
struct MeshEdge {
  int a = 0, b = 0;
  int uses = 0;
  int forward = 0;
};

// Inputs: mesh. Output: its distinct edges, ordered by (a, b), with their use counts.
std::vector<MeshEdge> mesh_edges(const QuadMesh& mesh);

}  // namespace autoblock
