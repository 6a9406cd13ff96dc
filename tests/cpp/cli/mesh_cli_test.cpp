// `autoblock mesh` as a contract: outputs, report fields, errors that leave nothing behind; and
// `autoblock decompose --out` writing the conformal compound.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <nlohmann/json.hpp>

#include "core/geometry/occt_face.h"
#include "core/io/shape_file.h"
#include "core/mesh/mesh_conformity.h"
#include "core/mesh/mesh_quality.h"
#include "support/bad_shapes.h"
#include "support/mesh_fixtures.h"
#include "support/mesh_readers.h"
#include "support/run_command.h"
#include "support/test_shapes.h"

using namespace autoblock;
using test::read_json;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

void check_input_error(const test::CommandResult& r, const std::string& expected) {
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, StartsWith("error: "));
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Contains(expected));
}

// An L-shaped face [0,4]^2 minus [2,4]^2 written to folder/l.brep.
std::string l_shape_file(const std::string& folder) {
  const std::string path = folder + "/l.brep";
  write_shape_file(path, occt_face_from_polygon(test::polygon_of({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}), 0, true));
  return path;
}

}  // namespace

TEST_CASE("autoblock mesh writes meshes, pictures and a report", "[cli][mesh]") {
  const std::string folder = test::temporary_folder("cli-mesh");
  REQUIRE(test::run_autoblock("generate --count 3 --seed 8 --holes --out '" + folder + "/set'").exit_code == 0);
  const std::vector<std::pair<std::string, std::string>> outputs{{"m.msh", "p.svg"}, {"m.vtu", "p.png"}, {"m.inp", "p.svg"}};
  for (int s = 0; s < 3; ++s) {
    const std::string shape = folder + "/set/shape_000" + std::to_string(s) + ".brep";
    const auto& [mesh_file, picture] = outputs[static_cast<size_t>(s)];
    const std::string policy = s == 1 ? "optimal" : "greedy";
    const auto r = test::run_autoblock("mesh '" + shape + "' --policy " + policy + " --out '" + folder + "/" + mesh_file +
                                       "' --picture '" + folder + "/" + picture + "' --json '" + folder + "/r.json'");
    INFO(shape << ": " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());
    CHECK_THAT(r.out, Contains("conformal"));
    const nlohmann::json report = read_json(folder + "/r.json");
    for (const char* key : {"input", "policy", "blocks", "nodes", "quads", "target_size", "intervals", "quality",
                            "conformal", "conformity", "seconds", "timing"}) {
      CHECK(report.contains(key));
    }
    CHECK(report["policy"] == policy);
    CHECK(report["conformal"] == true);
    CHECK(report["default_size"] == true);
    CHECK(report["quality"]["min_scaled_jacobian"] == 1.0);
    CHECK(report["quality"]["mean_scaled_jacobian"] == 1.0);
    CHECK(report["quality"]["irregular_interior_vertices"] == 0);
    CHECK(report["quality"]["bound"] == 1.0);  // a rectilinear face's corners allow right angles
    CHECK(report["quality"]["min_scaled_jacobian_over_bound"] == 1.0);
    CHECK(report["quality"]["max_aspect_ratio"].get<double>() >= 1.0);
    CHECK(report["intervals"]["max_deviation"].get<double>() >= 0.0);
    CHECK(report["seconds"].get<double>() > 0.0);
    const std::string text = test::slurp_file(folder + "/" + mesh_file);
    const QuadMesh mesh = mesh_file == "m.msh" ? test::read_msh41(text)
                          : mesh_file == "m.vtu" ? test::read_vtu(text)
                                                 : test::read_inp(text);
    CHECK(mesh.nodes.size() == report["nodes"].get<size_t>());
    CHECK(mesh.quads.size() == report["quads"].get<size_t>());
    CHECK(mesh.blocks == report["blocks"].get<int>());
    const InputFace face = load_input_face(shape);
    CHECK(check_conformity(mesh, face.planar.polygon).conformal);  // the file, checked again
    CHECK(report["target_size"].get<double>() == Approx(face.grid.size / 20));
    CHECK(std::filesystem::file_size(folder + "/" + picture) > 500);
  }
}

TEST_CASE("autoblock mesh: --size and --intervals", "[cli][mesh]") {
  const std::string folder = test::temporary_folder("cli-mesh-size");
  const std::string l_shape = l_shape_file(folder);
  const auto r = test::run_autoblock("mesh '" + l_shape + "' --size 0.5 --intervals 0,0,4,0=5 --out '" + folder +
                                     "/m.msh' --json '" + folder + "/r.json'");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json report = read_json(folder + "/r.json");
  CHECK(report["target_size"] == 0.5);
  CHECK(report["default_size"] == false);
  REQUIRE(report["intervals"]["fixed"].size() == 1);
  CHECK(report["intervals"]["fixed"][0]["intervals"] == 5);
  const QuadMesh mesh = test::read_msh41(test::slurp_file(folder + "/m.msh"));
  int bottom = 0;
  for (const Point2& p : mesh.nodes) bottom += p.y == 0;
  CHECK(bottom == 6);  // 5 intervals along the bottom, split 2 + 3 or 3 + 2 by the line x = 2
  CHECK(mesh_quality(mesh).min_scaled_jacobian == 1.0);
}

TEST_CASE("autoblock mesh: bad requests get exit 2, one line, and nothing written", "[cli][mesh][errors]") {
  const std::string folder = test::temporary_folder("cli-mesh-bad");
  const std::string l_shape = l_shape_file(folder);
  const std::string outputs = " --out '" + folder + "/m.msh' --json '" + folder + "/r.json' --picture '" + folder + "/p.svg'";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--intervals 0,0,4,0=1", "cannot have 1 interval"},
      {"--intervals 0,0,4,0=2 --intervals 0,4,2,4=3", "cannot all hold"},
      {"--intervals 0,0,4,0", "expected X0,Y0,X1,Y1=N"},
      {"--intervals 0,0,3,0=2", "not a corner coordinate"},
      {"--size 0", "--size"},
      {"--size -2", "--size"},
      {"--size 1e-5", "quadrilaterals (limit"},
      {"--policy nonsense", "nonsense"}};
  for (const auto& [arguments, expected] : cases) {
    const auto r = test::run_autoblock("mesh '" + l_shape + "' " + arguments + outputs);
    INFO(arguments);
    check_input_error(r, expected);
    CHECK_FALSE(std::filesystem::exists(folder + "/m.msh"));
    CHECK_FALSE(std::filesystem::exists(folder + "/r.json"));
    CHECK_FALSE(std::filesystem::exists(folder + "/p.svg"));
  }
  check_input_error(test::run_autoblock("mesh '" + l_shape + "' --out '" + folder + "/m.stl'"), "expected a .msh, .vtu or .inp");
  check_input_error(test::run_autoblock("mesh '" + l_shape + "' --picture '" + folder + "/p.jpg'"), "expected a .svg or .png");
  check_input_error(test::run_autoblock("mesh '" + l_shape + "' --json '" + folder + "/r.json' --out '" + folder + "/no/m.msh'"),
                    "does not exist");
  CHECK_FALSE(std::filesystem::exists(folder + "/r.json"));
  for (const test::BadShape& bad : test::bad_shapes()) {
    if (bad.name == "solid") continue;  // a box is a swept solid: `mesh` gives hexahedra (solid_cli_test.cpp)
    const std::string path = folder + "/" + bad.name + ".brep";
    write_shape_file(path, bad.shape);
    INFO(bad.name);
    check_input_error(test::run_autoblock("mesh '" + path + "'" + outputs), bad.expected);
    CHECK_FALSE(std::filesystem::exists(folder + "/r.json"));
  }
}

TEST_CASE("autoblock decompose --out writes a conformal compound", "[cli][merge]") {
  const std::string folder = test::temporary_folder("cli-conformal");
  REQUIRE(test::run_autoblock("generate --count 4 --seed 21 --holes --out '" + folder + "/set'").exit_code == 0);
  for (int s = 0; s < 4; ++s) {
    const std::string shape = folder + "/set/shape_000" + std::to_string(s) + ".brep";
    REQUIRE(test::run_autoblock("decompose '" + shape + "' --policy optimal --out '" + folder + "/b.brep'").exit_code == 0);
    ConformalBlocks model;
    model.compound = TopoDS::Compound(read_shape_file(folder + "/b.brep"));
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(model.compound, TopAbs_FACE, faces);
    for (int f = 1; f <= faces.Extent(); ++f) model.faces.push_back(TopoDS::Face(faces(f)));
    test::check_conformal_model(model, load_input_face(shape).planar.polygon);
  }
}
