#include "core/mesh/mesh_export.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/io/text_file.h"
#include "core/mesh/mesh_quality.h"
#include "core/mesh/msh41_writer.h"
#include "core/mesh/vtu_writer.h"

namespace autoblock {
namespace {

void put(std::string& out, long v) { out += std::to_string(v); }

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// A node's model coordinates.
std::array<double, 3> node_at(const QuadMesh& mesh, size_t id, const MeshPlacement& placement) {
  const Point2& p = mesh.nodes[id];
  return placement.apply(p.x, p.y, mesh.z);
}


}  // namespace

std::string gmsh_msh41(const QuadMesh& mesh, const MeshPlacement& placement) {
  std::vector<std::array<double, 3>> points;
  points.reserve(mesh.nodes.size());
  for (size_t id = 0; id < mesh.nodes.size(); ++id) points.push_back(node_at(mesh, id, placement));
  std::vector<MshEntity> blocks(static_cast<size_t>(mesh.blocks));
  for (size_t b = 0; b < blocks.size(); ++b) {
    blocks[b].tag = static_cast<int>(b) + 1;
    blocks[b].physical = "block_" + std::to_string(b + 1);
  }
  for (size_t q = 0; q < mesh.quads.size(); ++q) {
    const auto& quad = mesh.quads[q];
    blocks[static_cast<size_t>(mesh.quad_block[q])].elements.push_back({quad[0], quad[1], quad[2], quad[3]});
  }
  assign_msh_nodes(blocks, mesh.nodes.size());
  return msh41_text(points, blocks);
}

std::string vtk_vtu(const QuadMesh& mesh, const MeshPlacement& placement) {
  std::vector<std::array<double, 3>> points;
  points.reserve(mesh.nodes.size());
  for (size_t id = 0; id < mesh.nodes.size(); ++id) points.push_back(node_at(mesh, id, placement));
  VtuCells cells;
  cells.vtk_type = 9;
  cells.nodes_per_cell = 4;
  for (size_t q = 0; q < mesh.quads.size(); ++q) {
    cells.connectivity.insert(cells.connectivity.end(), mesh.quads[q].begin(), mesh.quads[q].end());
    cells.scaled_jacobian.push_back(quad_quality(mesh.corners(q)).scaled_jacobian);
  }
  cells.block = mesh.quad_block;
  return vtu_text(points, cells);
}

std::string abaqus_inp(const QuadMesh& mesh, const MeshPlacement& placement) {
  std::string out;
  out.reserve(mesh.nodes.size() * 48 + mesh.quads.size() * 40 + 1024);
  out += "*HEADING\nAutoBlock mapped mesh: " + std::to_string(mesh.nodes.size()) + " nodes, " +
         std::to_string(mesh.quads.size()) + " quadrilaterals, " + std::to_string(mesh.blocks) + " blocks\n";
  out += "*NODE, NSET=NALL\n";
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    out += std::to_string(n + 1) + ", ";
    append_point(out, node_at(mesh, n, placement), ", ");
    out += '\n';
  }
  std::vector<std::vector<size_t>> block_quads(static_cast<size_t>(mesh.blocks));
  for (size_t q = 0; q < mesh.quads.size(); ++q) block_quads[static_cast<size_t>(mesh.quad_block[q])].push_back(q);
  long tag = 1;
  std::vector<std::string> sets;
  for (size_t b = 0; b < block_quads.size(); ++b) {
    if (block_quads[b].empty()) continue;
    sets.push_back("BLOCK_" + std::to_string(b + 1));
    out += "*ELEMENT, TYPE=CPS4, ELSET=" + sets.back() + "\n";
    for (size_t q : block_quads[b]) {
      put(out, tag++);
      for (int id : mesh.quads[q]) {
        out += ", ";
        put(out, static_cast<long>(id) + 1);
      }
      out += '\n';
    }
  }
  out += "*ELSET, ELSET=EALL\n";
  for (size_t s = 0; s < sets.size(); ++s) {  // at most 8 entries per data line
    out += sets[s] + ((s + 1) % 8 == 0 || s + 1 == sets.size() ? "\n" : ", ");
  }
  return out;
}

bool is_mesh_file_name(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".msh" || ext == ".vtu" || ext == ".inp";
}

std::string mesh_file_text(const std::string& path, const QuadMesh& mesh, const MeshPlacement& placement) {
  const std::string ext = lower_extension(path);
  if (ext == ".msh") return gmsh_msh41(mesh, placement);
  if (ext == ".vtu") return vtk_vtu(mesh, placement);
  if (ext == ".inp") return abaqus_inp(mesh, placement);
  throw InputError(path + ": unknown mesh file type '" + ext + "' (expected .msh, .vtu or .inp)");
}

void write_mesh_file(const std::string& path, const QuadMesh& mesh, const MeshPlacement& placement) {
  write_text_file(path, mesh_file_text(path, mesh, placement));
}

}  // namespace autoblock
