#include "core/mesh/msh41_writer.h"

#include <algorithm>
#include <charconv>

namespace autoblock {

void append_shortest(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void append_point(std::string& out, const std::array<double, 3>& p, const char* separator) {
  append_shortest(out, p[0]);
  out += separator;
  append_shortest(out, p[1]);
  out += separator;
  append_shortest(out, p[2]);
}

void assign_msh_nodes(std::vector<MshEntity>& entities, size_t node_count) {
  std::vector<char> owned(node_count, 0);
  for (MshEntity& e : entities) {
    e.nodes.clear();
    for (const auto& element : e.elements) {
      for (int id : element) {
        if (!owned[static_cast<size_t>(id)]) {
          owned[static_cast<size_t>(id)] = 1;
          e.nodes.push_back(id);
        }
      }
    }
  }
}

std::string msh41_text(const std::vector<std::array<double, 3>>& points, const std::vector<MshEntity>& entities) {
  size_t element_count = 0, node_blocks = 0, element_blocks = 0;
  int per_dim[4] = {0, 0, 0, 0};
  for (const MshEntity& e : entities) {
    element_count += e.elements.size();
    node_blocks += !e.nodes.empty();
    element_blocks += !e.elements.empty();
    ++per_dim[e.dim];
  }
  std::string out;
  out.reserve(points.size() * 48 + element_count * 48 + 1024);
  out += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n" + std::to_string(entities.size()) + "\n";
  for (const MshEntity& e : entities) {
    out += std::to_string(e.dim) + " " + std::to_string(e.tag) + " \"" + e.physical + "\"\n";
  }
  out += "$EndPhysicalNames\n$Entities\n" + std::to_string(per_dim[0]) + " " + std::to_string(per_dim[1]) + " " +
         std::to_string(per_dim[2]) + " " + std::to_string(per_dim[3]) + "\n";
  for (const MshEntity& e : entities) {
    std::array<double, 3> low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
    for (const auto& element : e.elements) {
      for (int id : element) {
        for (size_t k = 0; k < 3; ++k) {
          low[k] = std::min(low[k], points[static_cast<size_t>(id)][k]);
          high[k] = std::max(high[k], points[static_cast<size_t>(id)][k]);
        }
      }
    }
    out += std::to_string(e.tag);
    for (double v : {low[0], low[1], low[2], high[0], high[1], high[2]}) {
      out += ' ';
      append_shortest(out, v);
    }
    out += " 1 " + std::to_string(e.tag) + " 0\n";
  }
  out += "$EndEntities\n$Nodes\n" + std::to_string(node_blocks) + " " + std::to_string(points.size()) + " 1 " +
         std::to_string(points.size()) + "\n";
  for (const MshEntity& e : entities) {
    if (e.nodes.empty()) continue;
    out += std::to_string(e.dim) + " " + std::to_string(e.tag) + " 0 " + std::to_string(e.nodes.size()) + "\n";
    for (int id : e.nodes) out += std::to_string(id + 1) + "\n";
    for (int id : e.nodes) {
      append_point(out, points[static_cast<size_t>(id)], " ");
      out += '\n';
    }
  }
  out += "$EndNodes\n$Elements\n" + std::to_string(element_blocks) + " " + std::to_string(element_count) + " 1 " +
         std::to_string(element_count) + "\n";
  long tag = 1;
  for (const MshEntity& e : entities) {
    if (e.elements.empty()) continue;
    out += std::to_string(e.dim) + " " + std::to_string(e.tag) + " " + std::to_string(e.element_type) + " " +
           std::to_string(e.elements.size()) + "\n";
    for (const auto& element : e.elements) {
      out += std::to_string(tag++);
      for (int id : element) out += " " + std::to_string(id + 1);
      out += '\n';
    }
  }
  out += "$EndElements\n";
  return out;
}

}  // namespace autoblock
