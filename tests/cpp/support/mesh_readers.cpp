#include "support/mesh_readers.h"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace autoblock::test {
namespace {

void expect(std::istream& in, const std::string& word) {
  std::string got;
  if (!(in >> got) || got != word) throw std::runtime_error("expected " + word + ", read " + got);
}

// Renumbers tags to 0-based indices in increasing tag order.
QuadMesh assemble(const std::map<long, std::array<double, 3>>& nodes, const std::vector<std::array<long, 4>>& quads,
                  const std::vector<int>& blocks) {
  QuadMesh mesh;
  std::map<long, int> index;
  for (const auto& [tag, xyz] : nodes) {
    index[tag] = static_cast<int>(mesh.nodes.size());
    mesh.nodes.push_back(Point2{xyz[0], xyz[1]});
    mesh.z = xyz[2];
  }
  for (size_t q = 0; q < quads.size(); ++q) {
    std::array<int, 4> ids{};
    for (size_t k = 0; k < 4; ++k) {
      const auto it = index.find(quads[q][k]);
      if (it == index.end()) throw std::runtime_error("element refers to a missing node");
      ids[k] = it->second;
    }
    mesh.quads.push_back(ids);
    mesh.quad_block.push_back(blocks[q]);
    mesh.blocks = std::max(mesh.blocks, blocks[q] + 1);
  }
  return mesh;
}

// The text between <DataArray ... Name="name" ...> and </DataArray>.
std::string data_array(const std::string& text, const std::string& name) {
  size_t at = std::string::npos;
  if (name.empty()) {
    at = text.find("<Points>");
    at = text.find("<DataArray", at);
  } else {
    at = text.find("Name=\"" + name + "\"");
  }
  if (at == std::string::npos) throw std::runtime_error("no DataArray " + name);
  const size_t begin = text.find('>', at) + 1, end = text.find("</DataArray>", begin);
  return text.substr(begin, end - begin);
}

}  // namespace

QuadMesh read_msh41(const std::string& text) {
  std::istringstream in(text);
  std::map<long, std::array<double, 3>> nodes;
  std::vector<std::array<long, 4>> quads;
  std::vector<int> blocks;
  std::map<int, int> entity_physical;
  std::string section;
  while (in >> section) {
    if (section == "$MeshFormat") {
      std::string version;
      int type = 0, size = 0;
      in >> version >> type >> size;
      if (version != "4.1" || type != 0) throw std::runtime_error("not MSH 4.1 ASCII");
      expect(in, "$EndMeshFormat");
    } else if (section == "$Entities") {
      long points, curves, surfaces, volumes;
      in >> points >> curves >> surfaces >> volumes;
      if (points || curves || volumes) throw std::runtime_error("unexpected entities");
      for (long s = 0; s < surfaces; ++s) {
        int tag;
        double box[6];
        size_t n_physical;
        in >> tag;
        for (double& b : box) in >> b;
        in >> n_physical;
        int physical = 0;
        for (size_t p = 0; p < n_physical; ++p) in >> physical;
        entity_physical[tag] = physical;
        size_t n_curves;
        in >> n_curves;
        for (size_t c = 0; c < n_curves; ++c) in >> tag;
      }
      expect(in, "$EndEntities");
    } else if (section == "$Nodes") {
      long n_blocks, n_nodes, min_tag, max_tag;
      in >> n_blocks >> n_nodes >> min_tag >> max_tag;
      for (long b = 0; b < n_blocks; ++b) {
        int dim, entity, parametric;
        long count;
        in >> dim >> entity >> parametric >> count;
        std::vector<long> tags(static_cast<size_t>(count));
        for (long& t : tags) in >> t;
        for (long t : tags) {
          std::array<double, 3> xyz{};
          in >> xyz[0] >> xyz[1] >> xyz[2];
          if (!nodes.emplace(t, xyz).second) throw std::runtime_error("duplicate node tag");
        }
      }
      if (static_cast<long>(nodes.size()) != n_nodes) throw std::runtime_error("node count mismatch");
      expect(in, "$EndNodes");
    } else if (section == "$Elements") {
      long n_blocks, n_elements, min_tag, max_tag;
      in >> n_blocks >> n_elements >> min_tag >> max_tag;
      for (long b = 0; b < n_blocks; ++b) {
        int dim, entity, type;
        long count;
        in >> dim >> entity >> type >> count;
        if (dim != 2 || type != 3) throw std::runtime_error("expected 4-node quadrangles");
        for (long e = 0; e < count; ++e) {
          long tag;
          std::array<long, 4> q{};
          in >> tag >> q[0] >> q[1] >> q[2] >> q[3];
          quads.push_back(q);
          blocks.push_back(entity_physical.at(entity) - 1);
        }
      }
      if (static_cast<long>(quads.size()) != n_elements) throw std::runtime_error("element count mismatch");
      expect(in, "$EndElements");
    } else if (section == "$PhysicalNames") {
      std::string line;
      std::getline(in, line);
      std::getline(in, line);
      const int n = std::stoi(line);
      for (int k = 0; k < n; ++k) std::getline(in, line);
      expect(in, "$EndPhysicalNames");
    } else {
      throw std::runtime_error("unknown section " + section);
    }
    if (!in) throw std::runtime_error("truncated section " + section);
  }
  return assemble(nodes, quads, blocks);
}

QuadMesh read_vtu(const std::string& text) {
  if (text.find("type=\"UnstructuredGrid\"") == std::string::npos) throw std::runtime_error("not an unstructured grid");
  std::map<long, std::array<double, 3>> nodes;
  std::istringstream points(data_array(text, ""));
  std::array<double, 3> xyz{};
  for (long n = 0; points >> xyz[0] >> xyz[1] >> xyz[2]; ++n) nodes[n] = xyz;
  std::istringstream connectivity(data_array(text, "connectivity")), offsets(data_array(text, "offsets")),
      types(data_array(text, "types")), block(data_array(text, "block"));
  std::vector<std::array<long, 4>> quads;
  std::vector<int> blocks;
  long offset = 0, previous = 0;
  int type = 0, b = 0;
  while (offsets >> offset) {
    if (!(types >> type) || type != 9 || offset - previous != 4) throw std::runtime_error("expected VTK_QUAD cells");
    std::array<long, 4> q{};
    connectivity >> q[0] >> q[1] >> q[2] >> q[3];
    block >> b;
    quads.push_back(q);
    blocks.push_back(b - 1);
    previous = offset;
  }
  return assemble(nodes, quads, blocks);
}

QuadMesh read_inp(const std::string& text) {
  std::istringstream in(text);
  std::map<long, std::array<double, 3>> nodes;
  std::vector<std::array<long, 4>> quads;
  std::vector<int> blocks;
  std::string line, mode;
  int block = -1;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line[0] == '*') {
      mode = line.substr(0, line.find(','));
      if (mode == "*ELEMENT") {
        if (line.find("TYPE=CPS4") == std::string::npos) throw std::runtime_error("expected CPS4 elements");
        const size_t at = line.find("ELSET=BLOCK_");
        if (at == std::string::npos) throw std::runtime_error("element set without a block");
        block = std::stoi(line.substr(at + 12)) - 1;
      }
      continue;
    }
    for (char& c : line) c = c == ',' ? ' ' : c;
    std::istringstream fields(line);
    if (mode == "*NODE") {
      long tag;
      std::array<double, 3> xyz{};
      fields >> tag >> xyz[0] >> xyz[1] >> xyz[2];
      nodes[tag] = xyz;
    } else if (mode == "*ELEMENT") {
      long tag;
      std::array<long, 4> q{};
      fields >> tag >> q[0] >> q[1] >> q[2] >> q[3];
      if (!fields) throw std::runtime_error("bad element line");
      quads.push_back(q);
      blocks.push_back(block);
    }
  }
  return assemble(nodes, quads, blocks);
}

std::string slurp_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace autoblock::test
