// Mesh files: round trips through our readers and through Debian's gmsh; pictures.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <tuple>

#include "core/baselines/baseline_policy.h"
#include "core/env/decomposition.h"
#include "core/geometry/occt_face.h"
#include "core/io/svg_picture.h"
#include "core/io/text_file.h"
#include "core/mesh/mesh_conformity.h"
#include "core/mesh/mesh_export.h"
#include "core/mesh/mesh_picture.h"
#include "core/raster/picture_file.h"
#include "core/mesh/mesh_pipeline.h"
#include "support/mesh_readers.h"
#include "support/run_command.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;

namespace {

// A mesh of a generated face with holes.
struct Sample {
  InputFace face;
  Decomposition decomposition;
  QuadMesh mesh;
};

Sample sample(std::uint64_t seed, double z) {
  GeneratorOptions options;
  options.holes = true;
  const auto shapes = test::generated_shapes(1, seed, options);
  Sample s;
  s.face = input_face_from_occt(occt_face_from_polygon(shapes[0].polygon, z, true), "generated");
  auto policy = make_baseline_policy("greedy", s.face.grid.size, BaselineOptions{});
  s.decomposition = decompose_face(s.face.grid, *policy);
  s.mesh = mesh_decomposition(s.face, s.decomposition).mesh;
  return s;
}

// Every quad as (block, its four corner positions), sorted: equal for equal meshes whatever the
// numbering. quantum > 0 rounds coordinates to its multiples (for files written with 16 digits).
std::vector<std::tuple<int, double, double, double, double, double, double, double, double>> canonical(const QuadMesh& m,
                                                                                                       double quantum) {
  std::vector<std::tuple<int, double, double, double, double, double, double, double, double>> out;
  auto r = [&](double v) { return quantum > 0 ? std::round(v / quantum) * quantum : v; };
  for (size_t q = 0; q < m.quads.size(); ++q) {
    const auto c = m.corners(q);
    out.emplace_back(m.quad_block[q], r(c[0].x), r(c[0].y), r(c[1].x), r(c[1].y), r(c[2].x), r(c[2].y), r(c[3].x), r(c[3].y));
  }
  std::sort(out.begin(), out.end());
  return out;
}

void check_same(const QuadMesh& got, const QuadMesh& want, double quantum = 0.0) {
  CHECK(got.nodes.size() == want.nodes.size());
  CHECK(got.quads.size() == want.quads.size());
  CHECK(got.blocks == want.blocks);
  CHECK(got.z == Approx(want.z).margin(quantum));
  CHECK(canonical(got, quantum) == canonical(want, quantum));  // same quads in the same blocks
}

}  // namespace

TEST_CASE("mesh files read back to the same mesh", "[mesh][export]") {
  const Sample s = sample(5, 0.1 + 0.2);  // a z that is not a short decimal
  REQUIRE(s.mesh.quads.size() > 50);
  const QuadMesh msh = test::read_msh41(gmsh_msh41(s.mesh));
  check_same(msh, s.mesh);
  CHECK(msh.nodes == s.mesh.nodes);  // tags keep the numbering
  check_same(test::read_vtu(vtk_vtu(s.mesh)), s.mesh);
  check_same(test::read_inp(abaqus_inp(s.mesh)), s.mesh);
  CHECK(check_conformity(test::read_inp(abaqus_inp(s.mesh)), s.face.planar.polygon).conformal);
  CHECK_THROWS_WITH(mesh_file_text("mesh.stl", s.mesh), Contains("expected .msh, .vtu or .inp"));
  CHECK(is_mesh_file_name("A.MSH"));
}

TEST_CASE("mesh files can place the mesh where the face lies in the model", "[mesh][export]") {
  const Sample s = sample(6, 1.5);
  // A quarter turn about Z and a shift: (x, y, z) -> (10 - y, 20 + x, z + 5).
  MeshPlacement placement;
  placement.rotation = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  placement.translation = {10, 20, 5};
  CHECK_FALSE(placement.identity());
  CHECK(MeshPlacement{}.identity());
  QuadMesh moved = s.mesh;
  for (Point2& p : moved.nodes) p = Point2{10 - p.y, 20 + p.x};
  moved.z = s.mesh.z + 5;
  check_same(test::read_msh41(gmsh_msh41(s.mesh, placement)), moved, 1e-12);
  check_same(test::read_vtu(vtk_vtu(s.mesh, placement)), moved, 1e-12);
  check_same(test::read_inp(abaqus_inp(s.mesh, placement)), moved, 1e-12);
  // The identity writes the same text as no placement.
  CHECK(mesh_file_text("a.inp", s.mesh, MeshPlacement{}) == abaqus_inp(s.mesh));
  // A face of the XZ plane: the mesh's y becomes z.
  MeshPlacement side;
  side.rotation = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  const auto p = side.apply(2, 3, 0.5);
  CHECK(p[0] == 2);
  CHECK(p[1] == -0.5);
  CHECK(p[2] == 3);
  CHECK_THAT(abaqus_inp(s.mesh, side), Contains("\n1, "));
}

TEST_CASE("gmsh loads AutoBlock's .msh files and saves the same mesh", "[mesh][export][gmsh]") {
  const std::string folder = test::temporary_folder("gmsh");
  for (std::uint64_t seed : {11u, 12u, 13u}) {
    const Sample s = sample(seed, -1.0);
    const std::string mine = folder + "/mine" + std::to_string(seed) + ".msh";
    const std::string back = folder + "/back" + std::to_string(seed) + ".msh";
    write_mesh_file(mine, s.mesh);
    const test::CommandResult check = test::run_shell("gmsh -check '" + mine + "'");
    INFO(check.out << check.err);
    REQUIRE(check.exit_code == 0);
    const std::string said = check.out + check.err;
    CHECK_THAT(said, Contains("Info    : " + std::to_string(s.mesh.nodes.size()) + " nodes"));
    CHECK_THAT(said, Contains("Info    : " + std::to_string(s.mesh.quads.size()) + " elements"));
    CHECK_THAT(said, Contains("Info    : " + std::to_string(s.mesh.blocks) + " entities"));
    CHECK_FALSE(std::regex_search(said, std::regex("Error|Warning")));
    // Merge into gmsh and let it save the mesh again: the physical groups survive.
    write_text_file(folder + "/resave.geo", "Merge \"" + mine + "\";\nSave \"" + back + "\";\n");
    const test::CommandResult resave = test::run_shell("gmsh '" + folder + "/resave.geo' -0");
    REQUIRE(resave.exit_code == 0);
    const std::string text = test::slurp_file(back);
    CHECK_THAT(text, Contains("\"block_" + std::to_string(s.mesh.blocks) + "\""));
    check_same(test::read_msh41(text), s.mesh, 1e-9);  // gmsh writes 16 significant digits
  }
}

TEST_CASE("mesh pictures: SVG, and PNG rasterised from it", "[mesh][export][picture]") {
  const Sample s = sample(7, 0.0);
  const std::string svg = mesh_svg(s.face.planar.polygon, s.decomposition.blocks, s.mesh, "title | line 2");
  CHECK_THAT(svg, Contains("<svg") && Contains("title") && Contains("line 2"));
  const std::string folder = test::temporary_folder("picture");
  write_picture(folder + "/p.PNG", svg);
  const std::string png = test::slurp_file(folder + "/p.PNG");
  REQUIRE(png.size() > 1000);
  CHECK(png.substr(1, 3) == "PNG");
  write_picture(folder + "/p.svg", svg);
  CHECK(test::slurp_file(folder + "/p.svg") == svg);
  CHECK_THROWS_WITH(write_picture(folder + "/p.jpg", svg), Contains("expected a .svg or .png file"));
}

TEST_CASE("a mesh picture leaves the face's holes white under a part finished around them", "[mesh][export][picture]") {
  const Ring outer{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, hole{{1, 1}, {1, 3}, {3, 3}, {3, 1}};
  const std::string svg = mesh_svg({outer, hole}, {outer}, QuadMesh{}, "a part with a hole");
  const size_t part = svg.find("<path fill=\"#");
  const size_t white = svg.find("<path fill=\"white\" d=\"M");
  REQUIRE(part != std::string::npos);
  REQUIRE(white != std::string::npos);
  CHECK(white > part);  // drawn over the part's fill
  const std::string path = svg.substr(white, svg.find("\"/>", white) - white);
  CHECK(std::count(path.begin(), path.end(), 'M') == 1);  // the hole alone, not the outer loop
  CHECK(std::count(path.begin(), path.end(), 'L') == 3);
  // A face without holes has no such path.
  CHECK(mesh_svg({outer}, {outer}, QuadMesh{}, "no hole").find("fill=\"white\" d=") == std::string::npos);
}

TEST_CASE("a mesh picture draws each part from its quads, part sides and the outline along mesh edges",
          "[mesh][export][picture]") {
  // Three quads in a row, the first two of part 0, the third of part 1. The parts' rings given (a
  // coarse polygon, as an arc's part would have) are not what is drawn: the mesh is.
  QuadMesh mesh;
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 4; ++x) mesh.nodes.push_back(Point2{static_cast<double>(x), static_cast<double>(y)});
  }
  mesh.quads = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}};
  mesh.quad_block = {0, 0, 1};
  mesh.blocks = 2;
  const Ring outer{{0, 0}, {3, 0}, {3, 1}, {0, 1}};
  const std::string svg = mesh_svg({outer}, {Ring{{0, 0}, {2, 0}, {2, 1}}, Ring{{2, 0}, {3, 0}, {3, 1}}}, mesh, "parts");
  // The path that follows a marker, up to its end.
  auto path_after = [&](const std::string& marker) {
    const size_t at = svg.find(marker);
    REQUIRE(at != std::string::npos);
    return svg.substr(at, svg.find("\"/>", at) - at);
  };
  auto count = [](const std::string& text, char c) { return std::count(text.begin(), text.end(), c); };
  // Each part filled within one loop of its quads' outline: part 0's six nodes, part 1's four.
  const std::string part0 = path_after("<path fill=\"" + block_colour(0) + "\"");
  CHECK(count(part0, 'M') == 1);
  CHECK(count(part0, 'L') == 5);
  const std::string part1 = path_after("<path fill=\"" + block_colour(1) + "\"");
  CHECK(count(part1, 'M') == 1);
  CHECK(count(part1, 'L') == 3);
  CHECK(count(path_after("stroke-width=\"1.6\""), 'M') == 1);  // the edge between the parts, x = 2
  CHECK(count(path_after("stroke-width=\"2.5\""), 'M') == 8);  // the mesh's boundary edges
  CHECK(count(path_after("stroke-width=\"0.6\""), 'M') == 10);  // every mesh edge
}
