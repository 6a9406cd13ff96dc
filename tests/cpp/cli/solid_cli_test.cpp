// `autoblock mesh SOLID`: a swept solid gives hexahedra (mesh files gmsh reads, the blocks as solids,
// a report, a picture); solids it cannot sweep and options that need a solid are one-line errors
// with nothing written.
#include <catch2/catch.hpp>

#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <filesystem>
#include <regex>

#include "core/geometry/occt_face.h"
#include "core/io/shape_file.h"
#include "support/mesh_readers.h"
#include "support/run_command.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

// An L with a square hole, swept obliquely by (1, 0.5, 3), as a STEP file in folder.
std::string solid_file(const std::string& folder) {
  const std::string path = folder + "/part.step";
  const RectilinearPolygon l = test::polygon_of({{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}}, {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}});
  write_shape_file(path, BRepPrimAPI_MakePrism(occt_face_from_polygon(l, 0, true), gp_Vec(1, 0.5, 3)).Shape());
  return path;
}

void check_input_error(const test::CommandResult& r, const std::string& expected) {
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, StartsWith("error: ") && Contains(expected));
  CHECK(test::line_count(r.err) == 1);
}

}  // namespace

TEST_CASE("autoblock mesh SOLID writes hexahedra, blocks, a report and a picture", "[cli][mesh][solid]") {
  const std::string folder = test::temporary_folder("cli-solid");
  const std::string part = solid_file(folder);
  const std::string msh = folder + "/m.msh", blocks = folder + "/b.brep", json = folder + "/r.json", svg = folder + "/p.svg";
  const auto r = test::run_autoblock("mesh '" + part + "' --policy greedy --size 0.5 --out '" + msh + "' --blocks '" + blocks +
                                     "' --json '" + json + "' --picture '" + svg + "'");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  CHECK_THAT(r.out, StartsWith(part + ": solid, caps Face") && Contains("hexahedra") && Contains(", conformal, "));
  const nlohmann::json report = test::read_json(json);
  CHECK(report["kind"] == "solid");
  CHECK(report["conformal"] == true);
  CHECK(report["layers"] == 6);  // |(1, 0.5, 3)| = 3.2 over 0.5
  CHECK(report["volume"].get<double>() == Approx(26.0 * 3));
  CHECK(report["conformity"]["hex_volume"].get<double>() == Approx(78.0).epsilon(1e-9));
  CHECK(report["sweep_angle"].get<double>() == Approx(std::acos(3 / std::sqrt(10.25)) * 180 / M_PI));
  CHECK(report["quality"]["min_scaled_jacobian"].get<double>() == Approx(3 / std::sqrt(10.25)));
  const int blocks_count = report["blocks"].get<int>();
  CHECK(blocks_count >= 4);

  // gmsh reads the mesh: nodes, hexahedra plus boundary quads, an entity per block and per face.
  const auto check = test::run_shell("gmsh -check '" + msh + "'");
  INFO(check.out << check.err);
  REQUIRE(check.exit_code == 0);
  const std::string said = check.out + check.err;
  CHECK_THAT(said, Contains("Info    : " + report["nodes"].dump() + " nodes"));
  CHECK_THAT(said, Contains("Info    : " + std::to_string(blocks_count + 12) + " entities"));  // the solid has 12 faces
  CHECK_FALSE(std::regex_search(said, std::regex("Error|Warning")));

  // The blocks: one solid each, filling the part.
  const TopoDS_Shape shape = read_shape_file(blocks);
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  CHECK(solids.Extent() == blocks_count);
  GProp_GProps volume;
  BRepGProp::VolumeProperties(shape, volume);
  CHECK(volume.Mass() == Approx(78.0));
  CHECK_THAT(test::slurp_file(svg), Contains("<svg") && Contains("<polygon"));

  // Layers, grading and the element type of the .inp.
  const std::string inp = folder + "/m.inp";
  const auto layered = test::run_autoblock("mesh '" + part + "' --policy greedy --layers 3 --grading 2 --element C3D8I --out '" +
                                           inp + "' --json '" + json + "'");
  INFO(layered.err);
  REQUIRE(layered.exit_code == 0);
  CHECK(test::read_json(json)["layers"] == 3);
  const std::string text = test::slurp_file(inp);
  CHECK_THAT(text, Contains("*ELEMENT, TYPE=C3D8I, ELSET=BLOCK_1") && Contains("*NSET, NSET=FACE_1") &&
                       Contains("*SURFACE, NAME=SFACE_12, TYPE=ELEMENT"));
}

TEST_CASE("autoblock decompose SOLID decomposes a cap and writes the blocks as prisms sharing their faces", "[cli][solid]") {
  const std::string folder = test::temporary_folder("cli-solid-decompose");
  const std::string part = solid_file(folder);
  // .brep keeps the shared faces (OpenCASCADE's STEP writer writes every solid on its own).
  const std::string out = folder + "/b.brep", json = folder + "/r.json";
  const auto r = test::run_autoblock("decompose '" + part + "' --policy optimal --out '" + out + "' --json '" + json + "'");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, StartsWith(part + ": solid, caps Face") && Contains(" swept): optimal: "));
  const nlohmann::json report = test::read_json(json);
  CHECK(report["solid"]["volume"].get<double>() == Approx(78.0));
  CHECK(report["solid"]["sweep"][2].get<double>() * report["solid"]["sweep"][2].get<double>() == Approx(9.0));
  const TopoDS_Shape shape = read_shape_file(out);
  TopTools_IndexedMapOfShape solids, faces;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  CHECK(solids.Extent() == report["n_blocks"].get<int>());
  GProp_GProps volume;
  BRepGProp::VolumeProperties(shape, volume);
  CHECK(volume.Mass() == Approx(78.0));
  // Shared faces: fewer distinct faces than the prisms have together.
  int prism_faces = 0;
  for (int k = 1; k <= solids.Extent(); ++k) {
    TopTools_IndexedMapOfShape own;
    TopExp::MapShapes(solids(k), TopAbs_FACE, own);
    prism_faces += own.Extent();
  }
  CHECK(faces.Extent() < prism_faces);
  const auto step = test::run_autoblock("decompose '" + part + "' --policy optimal --out '" + folder + "/b.step'");
  REQUIRE(step.exit_code == 0);
  GProp_GProps step_volume;
  BRepGProp::VolumeProperties(read_shape_file(folder + "/b.step"), step_volume);
  CHECK(step_volume.Mass() == Approx(78.0));
}

TEST_CASE("autoblock mesh SOLID: solids it cannot sweep and misplaced options are one-line errors", "[cli][mesh][solid][errors]") {
  const std::string folder = test::temporary_folder("cli-solid-bad");
  const std::string cone = folder + "/cone.brep";
  write_shape_file(cone, BRepPrimAPI_MakeCone(1, 0.5, 2).Shape());
  const std::string outputs = " --out '" + folder + "/m.msh' --json '" + folder + "/r.json' --blocks '" + folder + "/b.brep'";
  check_input_error(test::run_autoblock("mesh '" + cone + "'" + outputs), cone + ": face 1 is curved (a cone)");
  const std::string part = solid_file(folder);
  check_input_error(test::run_autoblock("mesh '" + part + "' --blocks '" + folder + "/b.txt'"), "expected a .brep");
  check_input_error(test::run_autoblock("mesh '" + part + "' --layers 0"), "--layers");
  check_input_error(test::run_autoblock("mesh '" + part + "' --grading -1"), "--grading");
  check_input_error(test::run_autoblock("mesh '" + part + "' --size 1e-4" + outputs), "hexahedra (limit 5000000)");
  // A face of the part (--face) is meshed as a face, where the solid's options make no sense.
  check_input_error(test::run_autoblock("mesh '" + part + "' --face 1 --layers 2"), "--layers is for solids");
  for (const char* name : {"m.msh", "r.json", "b.brep"}) CHECK_FALSE(std::filesystem::exists(folder + "/" + name));
}
