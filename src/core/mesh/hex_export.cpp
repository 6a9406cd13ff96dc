#include "core/mesh/hex_export.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

#include "core/common/error.h"
#include "core/mesh/hex_quality.h"
#include "core/mesh/msh41_writer.h"
#include "core/mesh/vtu_writer.h"

namespace autoblock {
namespace {

// The boundary quads per face of the solid, in face order.
std::map<int, std::vector<BoundaryQuad>> quads_by_face(const HexMesh& mesh) {
  std::map<int, std::vector<BoundaryQuad>> out;
  for (const BoundaryQuad& b : mesh.boundary) out[b.face].push_back(b);
  return out;
}

// Items joined by ", ", at most 16 per data line (Abaqus's limit).
void put_list(std::string& out, const std::vector<std::string>& items) {
  for (size_t k = 0; k < items.size(); ++k) out += items[k] + ((k + 1) % 16 == 0 || k + 1 == items.size() ? "\n" : ", ");
}

}  // namespace

std::string gmsh_msh41(const HexMesh& mesh) {
  std::vector<MshEntity> volumes(static_cast<size_t>(mesh.blocks));
  for (size_t b = 0; b < volumes.size(); ++b) {
    volumes[b].dim = 3;
    volumes[b].tag = static_cast<int>(b) + 1;
    volumes[b].physical = "block_" + std::to_string(b + 1);
    volumes[b].element_type = 5;
  }
  for (size_t h = 0; h < mesh.hexes.size(); ++h) {
    volumes[static_cast<size_t>(mesh.hex_block[h])].elements.emplace_back(mesh.hexes[h].begin(), mesh.hexes[h].end());
  }
  assign_msh_nodes(volumes, mesh.nodes.size());  // nodes belong to the blocks, surfaces list none
  std::vector<MshEntity> entities;
  for (const auto& [face, quads] : quads_by_face(mesh)) {
    MshEntity e;
    e.dim = 2;
    e.tag = face;
    e.physical = "face_" + std::to_string(face);
    e.element_type = 3;
    for (const BoundaryQuad& q : quads) {
      const std::array<int, 4> f = hex_face_nodes(mesh.hexes[static_cast<size_t>(q.hex)], q.side);
      e.elements.emplace_back(f.begin(), f.end());
    }
    entities.push_back(std::move(e));
  }
  entities.insert(entities.end(), volumes.begin(), volumes.end());
  return msh41_text(mesh.nodes, entities);
}

std::string vtk_vtu(const HexMesh& mesh) {
  VtuCells cells;
  cells.vtk_type = 12;
  cells.nodes_per_cell = 8;
  for (size_t h = 0; h < mesh.hexes.size(); ++h) {
    cells.connectivity.insert(cells.connectivity.end(), mesh.hexes[h].begin(), mesh.hexes[h].end());
    cells.scaled_jacobian.push_back(hex_quality(mesh.corners(h)).scaled_jacobian);
  }
  cells.block = mesh.hex_block;
  return vtu_text(mesh.nodes, cells);
}

std::string abaqus_inp(const HexMesh& mesh, const std::string& element_type) {
  if (element_type != "C3D8" && element_type != "C3D8I") {
    throw InputError("the element type " + element_type + " is not a hexahedron AutoBlock writes (C3D8 or C3D8I)");
  }
  std::string out;
  out.reserve(mesh.nodes.size() * 60 + mesh.hexes.size() * 80 + 1024);
  out += "*HEADING\nAutoBlock swept hexahedral mesh: " + std::to_string(mesh.nodes.size()) + " nodes, " +
         std::to_string(mesh.hexes.size()) + " hexahedra, " + std::to_string(mesh.blocks) + " blocks\n";
  out += "*NODE, NSET=NALL\n";
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    out += std::to_string(n + 1) + ", ";
    append_point(out, mesh.nodes[n], ", ");
    out += '\n';
  }
  // Elements numbered block by block: element[h] is hexahedron h's number.
  std::vector<std::vector<size_t>> block_hexes(static_cast<size_t>(mesh.blocks));
  for (size_t h = 0; h < mesh.hexes.size(); ++h) block_hexes[static_cast<size_t>(mesh.hex_block[h])].push_back(h);
  std::vector<long> element(mesh.hexes.size(), 0);
  long tag = 1;
  std::vector<std::string> sets;
  for (size_t b = 0; b < block_hexes.size(); ++b) {
    if (block_hexes[b].empty()) continue;
    sets.push_back("BLOCK_" + std::to_string(b + 1));
    out += "*ELEMENT, TYPE=" + element_type + ", ELSET=" + sets.back() + "\n";
    for (size_t h : block_hexes[b]) {
      element[h] = tag;
      out += std::to_string(tag++);
      for (int id : mesh.hexes[h]) out += ", " + std::to_string(id + 1);
      out += '\n';
    }
  }
  out += "*ELSET, ELSET=EALL\n";
  put_list(out, sets);
  for (const auto& [face, quads] : quads_by_face(mesh)) {
    std::set<int> nodes;
    for (const BoundaryQuad& q : quads) {
      for (int id : hex_face_nodes(mesh.hexes[static_cast<size_t>(q.hex)], q.side)) nodes.insert(id + 1);
    }
    std::vector<std::string> ids;
    for (int id : nodes) ids.push_back(std::to_string(id));
    out += "*NSET, NSET=FACE_" + std::to_string(face) + "\n";
    put_list(out, ids);
    out += "*SURFACE, NAME=SFACE_" + std::to_string(face) + ", TYPE=ELEMENT\n";
    for (const BoundaryQuad& q : quads) {
      out += std::to_string(element[static_cast<size_t>(q.hex)]) + ", S" + std::to_string(q.side + 1) + "\n";
    }
  }
  return out;
}

std::string mesh_file_text(const std::string& path, const HexMesh& mesh, const std::string& element_type) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".msh") return gmsh_msh41(mesh);
  if (ext == ".vtu") return vtk_vtu(mesh);
  if (ext == ".inp") return abaqus_inp(mesh, element_type);
  throw InputError(path + ": unknown mesh file type '" + ext + "' (expected .msh, .vtu or .inp)");
}

}  // namespace autoblock
