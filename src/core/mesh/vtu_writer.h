// The text of a VTK .vtu file (XML, ASCII) for a mesh of one cell type with the cell data AutoBlock
// writes: the one writer behind the quad (mesh_export.h) and hexahedral (hex_export.h) meshes.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace autoblock {

struct VtuCells {
  int vtk_type = 9;                      // 9 VTK_QUAD, 12 VTK_HEXAHEDRON
  int nodes_per_cell = 4;
  std::vector<int> connectivity;         // nodes_per_cell 0-based node ids per cell, cell after cell
  std::vector<int> block;                // per cell, 0-based (written 1-based as "block")
  std::vector<double> scaled_jacobian;   // per cell ("scaled_jacobian")
};

// Inputs: points, every node's coordinates; cells. Output: the file's text (coordinates and values as
// the shortest text that reads back to the same double).
std::string vtu_text(const std::vector<std::array<double, 3>>& points, const VtuCells& cells);

}  // namespace autoblock
