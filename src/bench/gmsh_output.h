// A gmsh .msh 4.1 ASCII file as the benchmarks read it back: the nodes and the elements by type.
//
// Inputs: path of a file gmsh wrote (`-format msh41`).
// Output: nodes (x, y, z, in file order) and, per gmsh element type (2 triangle, 3 quad, 5 hexahedron,
//         6 prism, ...), each element's nodes as indices into nodes. Throws std::runtime_error for an
//         element type it does not know.
#pragma once

#include <array>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace autoblock::bench {

struct GmshOutput {
  std::vector<std::array<double, 3>> nodes;
  std::map<int, std::vector<std::vector<int>>> elements;  // by gmsh element type
};

inline GmshOutput read_gmsh_output_file(const std::string& path) {
  static const std::map<int, int> nodes_per_type{{15, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 4}, {5, 8}, {6, 6}, {7, 5}};
  std::ifstream in(path);
  std::string word;
  GmshOutput out;
  std::map<long, int> index;
  while (in >> word) {
    if (word == "$Nodes") {
      long blocks, count, lo, hi;
      in >> blocks >> count >> lo >> hi;
      for (long b = 0; b < blocks; ++b) {
        int dim, tag, parametric;
        long n;
        in >> dim >> tag >> parametric >> n;
        std::vector<long> tags(static_cast<size_t>(n));
        for (long& t : tags) in >> t;
        for (long t : tags) {
          std::array<double, 3> p{};
          double u;
          in >> p[0] >> p[1] >> p[2];
          for (int k = 0; k < (parametric ? dim : 0); ++k) in >> u;
          index[t] = static_cast<int>(out.nodes.size());
          out.nodes.push_back(p);
        }
      }
    } else if (word == "$Elements") {
      long blocks, count, lo, hi;
      in >> blocks >> count >> lo >> hi;
      for (long b = 0; b < blocks; ++b) {
        int dim, tag, type;
        long n;
        in >> dim >> tag >> type >> n;
        const auto per = nodes_per_type.find(type);
        if (per == nodes_per_type.end()) throw std::runtime_error("gmsh output: element type " + std::to_string(type));
        auto& list = out.elements[type];
        for (long e = 0; e < n; ++e) {
          long element, v;
          in >> element;
          std::vector<int> nodes;
          for (int k = 0; k < per->second; ++k) {
            in >> v;
            nodes.push_back(index.at(v));
          }
          list.push_back(std::move(nodes));
        }
      }
    }
  }
  return out;
}

}  // namespace autoblock::bench
