#include "core/mesh/mesh_export.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <string>
#include <vector>

#include "core/common/error.h"
#include "core/io/text_file.h"
#include "core/mesh/mesh_quality.h"

namespace autoblock {
namespace {

// Shortest round-trip text of a double (std::to_chars).
void put(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void put(std::string& out, long v) { out += std::to_string(v); }

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

struct Bounds {
  double xmin = 1e300, ymin = 1e300, zmin = 1e300, xmax = -1e300, ymax = -1e300, zmax = -1e300;
  void add(const std::array<double, 3>& p) {
    xmin = std::min(xmin, p[0]);
    ymin = std::min(ymin, p[1]);
    zmin = std::min(zmin, p[2]);
    xmax = std::max(xmax, p[0]);
    ymax = std::max(ymax, p[1]);
    zmax = std::max(zmax, p[2]);
  }
};

// A node's model coordinates.
std::array<double, 3> node_at(const QuadMesh& mesh, size_t id, const MeshPlacement& placement) {
  const Point2& p = mesh.nodes[id];
  return placement.apply(p.x, p.y, mesh.z);
}

// "x<sep>y<sep>z" of a node.
void put_node(std::string& out, const QuadMesh& mesh, size_t id, const MeshPlacement& placement, const char* sep) {
  const std::array<double, 3> p = node_at(mesh, id, placement);
  put(out, p[0]);
  out += sep;
  put(out, p[1]);
  out += sep;
  put(out, p[2]);
}

}  // namespace

std::string gmsh_msh41(const QuadMesh& mesh, const MeshPlacement& placement) {
  const size_t n_blocks = static_cast<size_t>(mesh.blocks);
  // Owner block of every node (first block using it), quads and bounds per block.
  std::vector<int> owner(mesh.nodes.size(), -1);
  std::vector<std::vector<size_t>> block_quads(n_blocks), block_nodes(n_blocks);
  std::vector<Bounds> bounds(n_blocks);
  for (size_t q = 0; q < mesh.quads.size(); ++q) {
    const size_t b = static_cast<size_t>(mesh.quad_block[q]);
    block_quads[b].push_back(q);
    for (int id : mesh.quads[q]) bounds[b].add(node_at(mesh, static_cast<size_t>(id), placement));
  }
  for (size_t b = 0; b < n_blocks; ++b) {
    for (size_t q : block_quads[b]) {
      for (int id : mesh.quads[q]) {
        if (owner[static_cast<size_t>(id)] < 0) {
          owner[static_cast<size_t>(id)] = static_cast<int>(b);
          block_nodes[b].push_back(static_cast<size_t>(id));
        }
      }
    }
  }
  std::string out;
  out.reserve(mesh.nodes.size() * 48 + mesh.quads.size() * 40 + 1024);
  out += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n" + std::to_string(n_blocks) + "\n";
  for (size_t b = 0; b < n_blocks; ++b) {
    out += "2 " + std::to_string(b + 1) + " \"block_" + std::to_string(b + 1) + "\"\n";
  }
  out += "$EndPhysicalNames\n$Entities\n0 0 " + std::to_string(n_blocks) + " 0\n";
  for (size_t b = 0; b < n_blocks; ++b) {
    out += std::to_string(b + 1);
    for (double v : {bounds[b].xmin, bounds[b].ymin, bounds[b].zmin, bounds[b].xmax, bounds[b].ymax, bounds[b].zmax}) {
      out += ' ';
      put(out, v);
    }
    out += " 1 " + std::to_string(b + 1) + " 0\n";
  }
  out += "$EndEntities\n$Nodes\n";
  size_t node_blocks = 0;
  for (const auto& nodes : block_nodes) node_blocks += !nodes.empty();
  out += std::to_string(node_blocks) + " " + std::to_string(mesh.nodes.size()) + " 1 " + std::to_string(mesh.nodes.size()) + "\n";
  for (size_t b = 0; b < n_blocks; ++b) {
    if (block_nodes[b].empty()) continue;
    out += "2 " + std::to_string(b + 1) + " 0 " + std::to_string(block_nodes[b].size()) + "\n";
    for (size_t id : block_nodes[b]) out += std::to_string(id + 1) + "\n";
    for (size_t id : block_nodes[b]) {
      put_node(out, mesh, id, placement, " ");
      out += '\n';
    }
  }
  out += "$EndNodes\n$Elements\n";
  size_t element_blocks = 0;
  for (const auto& quads : block_quads) element_blocks += !quads.empty();
  out += std::to_string(element_blocks) + " " + std::to_string(mesh.quads.size()) + " 1 " + std::to_string(mesh.quads.size()) + "\n";
  long tag = 1;
  for (size_t b = 0; b < n_blocks; ++b) {
    if (block_quads[b].empty()) continue;
    out += "2 " + std::to_string(b + 1) + " 3 " + std::to_string(block_quads[b].size()) + "\n";
    for (size_t q : block_quads[b]) {
      put(out, tag++);
      for (int id : mesh.quads[q]) {
        out += ' ';
        put(out, static_cast<long>(id) + 1);
      }
      out += '\n';
    }
  }
  out += "$EndElements\n";
  return out;
}

std::string vtk_vtu(const QuadMesh& mesh, const MeshPlacement& placement) {
  std::string out;
  out.reserve(mesh.nodes.size() * 48 + mesh.quads.size() * 64 + 1024);
  out += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n";
  out += "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(mesh.nodes.size()) + "\" NumberOfCells=\"" +
         std::to_string(mesh.quads.size()) + "\">\n";
  out += "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (size_t id = 0; id < mesh.nodes.size(); ++id) {
    put_node(out, mesh, id, placement, " ");
    out += '\n';
  }
  out += "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& q : mesh.quads) {
    out += std::to_string(q[0]) + ' ' + std::to_string(q[1]) + ' ' + std::to_string(q[2]) + ' ' + std::to_string(q[3]) + '\n';
  }
  out += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (size_t q = 0; q < mesh.quads.size(); ++q) out += std::to_string(4 * (q + 1)) + '\n';
  out += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (size_t q = 0; q < mesh.quads.size(); ++q) out += "9\n";
  out += "</DataArray>\n</Cells>\n<CellData Scalars=\"block\">\n<DataArray type=\"Int32\" Name=\"block\" format=\"ascii\">\n";
  for (int b : mesh.quad_block) out += std::to_string(b + 1) + '\n';
  out += "</DataArray>\n<DataArray type=\"Float64\" Name=\"scaled_jacobian\" format=\"ascii\">\n";
  for (size_t q = 0; q < mesh.quads.size(); ++q) {
    put(out, quad_quality(mesh.corners(q)).scaled_jacobian);
    out += '\n';
  }
  out += "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return out;
}

std::string abaqus_inp(const QuadMesh& mesh, const MeshPlacement& placement) {
  std::string out;
  out.reserve(mesh.nodes.size() * 48 + mesh.quads.size() * 40 + 1024);
  out += "*HEADING\nAutoBlock mapped mesh: " + std::to_string(mesh.nodes.size()) + " nodes, " +
         std::to_string(mesh.quads.size()) + " quadrilaterals, " + std::to_string(mesh.blocks) + " blocks\n";
  out += "*NODE, NSET=NALL\n";
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    out += std::to_string(n + 1) + ", ";
    put_node(out, mesh, n, placement, ", ");
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
