// Hexahedral mesh files: gmsh reads the .msh back (entities, physical groups, element counts), and
// the .vtu and .inp hold what they promise (read back by plain parsing, not by the writers' code).
#include <catch2/catch.hpp>

#include <regex>
#include <set>
#include <sstream>

#include "core/common/error.h"
#include "core/io/text_file.h"
#include "core/mesh/hex_export.h"
#include "core/mesh/hex_quality.h"
#include "support/mesh_readers.h"
#include "support/run_command.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;

namespace {

// A 3 x 2 grid of quads (blocks: x < 1 and x > 1) swept obliquely in 3 layers; faces 1 bottom,
// 2 top, 3..6 the sides.
HexMesh sample() {
  QuadMesh cap;
  for (int j = 0; j <= 2; ++j) {
    for (int i = 0; i <= 3; ++i) cap.nodes.push_back({double(i), double(j)});
  }
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 3; ++i) {
      const int a = j * 4 + i;
      cap.quads.push_back({a, a + 1, a + 5, a + 4});
      cap.quad_block.push_back(i < 1 ? 0 : 1);
    }
  }
  cap.blocks = 2;
  cap.z = 0.5;
  SweepFrame w;
  w.sweep = {0.5, 0.25, 2};
  w.bottom_face = 1;
  w.top_face = 2;
  w.side_face = [](const Point3& a, const Point3& b, int) {
    const double x = (a[0] + b[0]) / 2, y = (a[1] + b[1]) / 2;
    return y == 0 ? 3 : x == 3 ? 4 : y == 2 ? 5 : 6;
  };
  return sweep_quad_mesh(cap, w, layer_stations(3, 1.2));
}

// The data lines after a keyword line starting with head, up to the next keyword.
std::vector<std::string> inp_block(const std::string& text, const std::string& head) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> out;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '*') {
      inside = line.rfind(head, 0) == 0;
      continue;
    }
    if (inside) out.push_back(line);
  }
  return out;
}

}  // namespace

TEST_CASE("hexahedral .msh: gmsh reads it, and saves it again with its physical groups", "[mesh][hex][export][gmsh]") {
  const HexMesh m = sample();
  const std::string folder = test::temporary_folder("hex-gmsh");
  const std::string mine = folder + "/hex.msh", back = folder + "/back.msh";
  write_text_file(mine, mesh_file_text(mine, m));
  const test::CommandResult check = test::run_shell("gmsh -check '" + mine + "'");
  INFO(check.out << check.err);
  REQUIRE(check.exit_code == 0);
  const std::string said = check.out + check.err;
  CHECK_THAT(said, Contains("Info    : " + std::to_string(m.nodes.size()) + " nodes"));
  CHECK_THAT(said, Contains("Info    : " + std::to_string(m.hexes.size() + m.boundary.size()) + " elements"));
  CHECK_THAT(said, Contains("Info    : " + std::to_string(6 + 2) + " entities"));  // 6 faces, 2 blocks
  CHECK_FALSE(std::regex_search(said, std::regex("Error|Warning")));
  write_text_file(folder + "/resave.geo", "Merge \"" + mine + "\";\nSave \"" + back + "\";\n");
  const test::CommandResult resave = test::run_shell("gmsh '" + folder + "/resave.geo' -0");
  REQUIRE(resave.exit_code == 0);
  const std::string text = test::slurp_file(back);
  CHECK_THAT(text, Contains("3 2 \"block_2\"") && Contains("2 6 \"face_6\""));
  // gmsh's own file: as many hexahedra (type 5) and quads (type 3) as ours, in the same entities.
  CHECK_THAT(text, Contains("\n3 1 5 " + std::to_string(6) + "\n") || Contains("\n3 1 5 6\n"));
}

TEST_CASE("hexahedral .vtu and .inp: cells, blocks, scaled Jacobians, element sets, node sets, surfaces", "[mesh][hex][export]") {
  const HexMesh m = sample();
  const std::string vtu = vtk_vtu(m);
  CHECK_THAT(vtu, Contains("NumberOfCells=\"" + std::to_string(m.hexes.size()) + "\""));
  CHECK_THAT(vtu, Contains("Name=\"block\"") && Contains("Name=\"scaled_jacobian\""));
  const size_t types = vtu.find("Name=\"types\"");
  REQUIRE(types != std::string::npos);
  std::istringstream cells(vtu.substr(vtu.find('\n', types) + 1));
  int twelve = 0;
  std::string word;
  while (cells >> word && word == "12") ++twelve;
  CHECK(twelve == static_cast<int>(m.hexes.size()));

  const std::string inp = abaqus_inp(m, "C3D8I");
  CHECK(inp_block(inp, "*NODE").size() == m.nodes.size());
  CHECK(inp_block(inp, "*ELEMENT, TYPE=C3D8I, ELSET=BLOCK_1").size() == 2 * 3);
  CHECK(inp_block(inp, "*ELEMENT, TYPE=C3D8I, ELSET=BLOCK_2").size() == 4 * 3);
  CHECK(inp_block(inp, "*ELSET, ELSET=EALL") == std::vector<std::string>{"BLOCK_1, BLOCK_2"});
  // Face 1 (the bottom cap): its 12 nodes, and its 6 element faces, all S1.
  std::set<std::string> nodes;
  for (const std::string& line : inp_block(inp, "*NSET, NSET=FACE_1")) {
    std::istringstream items(line);
    std::string item;
    while (std::getline(items, item, ',')) nodes.insert(item.substr(item.find_first_not_of(' ')));
  }
  CHECK(nodes.size() == 12);
  const std::vector<std::string> surface = inp_block(inp, "*SURFACE, NAME=SFACE_1, TYPE=ELEMENT");
  CHECK(surface.size() == 6);
  for (const std::string& line : surface) CHECK_THAT(line, Contains(", S1"));
  CHECK(inp_block(inp, "*SURFACE, NAME=SFACE_2, TYPE=ELEMENT").size() == 6);
  CHECK(inp_block(inp, "*SURFACE, NAME=SFACE_4, TYPE=ELEMENT").size() == 2 * 3);
  CHECK_THROWS_AS(abaqus_inp(m, "C3D20"), InputError);
  CHECK_THROWS_AS(mesh_file_text("m.stl", m), InputError);
  CHECK(mesh_file_text("M.INP", m) == abaqus_inp(m));
}
