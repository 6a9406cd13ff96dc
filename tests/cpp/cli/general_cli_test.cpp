// `autoblock generate --kind` and `autoblock decompose` on general faces (edges at any angle).
#include <catch2/catch.hpp>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "support/run_command.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;

TEST_CASE("autoblock decomposes generated general faces: report, picture and OpenCASCADE blocks", "[cli][general]") {
  const std::string folder = test::temporary_folder("cli-general");
  REQUIRE(test::run_autoblock("generate --kind polygon --holes --count 2 --seed 4 --out '" + folder + "/poly'").exit_code == 0);
  REQUIRE(test::run_autoblock("generate --kind chamfered --count 1 --seed 4 --out '" + folder + "/cham'").exit_code == 0);
  const nlohmann::json index = test::read_json(folder + "/poly/index.json");
  CHECK(index["generator"]["kind"] == "polygon");
  CHECK(index["shapes"].size() == 2);
  for (const std::string file : {"/poly/shape_0000.brep", "/poly/shape_0001.brep", "/cham/shape_0000.brep"}) {
    const auto r = test::run_autoblock("decompose '" + folder + file + "' --policy greedy --out '" + folder +
                                       "/b.brep' --json '" + folder + "/r.json' --picture '" + folder + "/p.svg'");
    INFO(file << "\n" << r.out << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Contains("greedy (general engine)"));
    const nlohmann::json report = test::read_json(folder + "/r.json");
    CHECK(report["engine"] == "general");
    CHECK(report["complete"] == true);
    CHECK(report["blocks"].size() == report["n_blocks"].get<size_t>() + report["n_templates"].get<size_t>());
    double area = 0;
    for (const auto& block : report["blocks"]) {
      const auto& outline = block["outline"];
      for (size_t i = 0; i < outline.size(); ++i) {
        const auto& a = outline[i];
        const auto& b = outline[(i + 1) % outline.size()];
        area += 0.5 * (a[0].get<double>() * b[1].get<double>() - b[0].get<double>() * a[1].get<double>());
      }
    }
    CHECK(area == Approx(report["face"]["area"].get<double>()).epsilon(1e-6));
    CHECK(std::filesystem::file_size(folder + "/b.brep") > 0);
    CHECK(std::filesystem::file_size(folder + "/p.svg") > 0);
  }
  // Meshing general blocks: every file written, the independent check passed, areas exact.
  const auto mesh = test::run_autoblock("mesh '" + folder + "/poly/shape_0000.brep' --policy greedy --out '" + folder +
                                        "/m.msh' --json '" + folder + "/m.json' --picture '" + folder + "/m.svg'");
  INFO(mesh.out << mesh.err);
  REQUIRE(mesh.exit_code == 0);
  CHECK_THAT(mesh.out, Contains("of the bound"));
  const nlohmann::json report = test::read_json(folder + "/m.json");
  CHECK(report["conformal"] == true);
  CHECK(report["quads"].get<int>() > 0);
  CHECK(report["intervals"]["edges"].get<int>() > 0);
  CHECK(report["conformity"]["quad_area"].get<double>() ==
        Approx(report["conformity"]["face_area"].get<double>()).epsilon(1e-6));  // the lattice: within its quantum
  const double bound = report["quality"]["bound"].get<double>();
  CHECK((bound > 0.0 && bound <= 1.0));
  CHECK(report["quality"]["min_scaled_jacobian"].get<double>() > 0.0);
  // Smoothing (on by default) never lowers the minimum.
  CHECK(report["smoothing"]["sweeps"].get<int>() > 0);
  CHECK(report["quality"]["min_scaled_jacobian"].get<double>() >=
        report["smoothing"]["min_scaled_jacobian_before"].get<double>());
  CHECK(std::filesystem::file_size(folder + "/m.msh") > 0);
  CHECK(std::filesystem::file_size(folder + "/m.svg") > 0);
  // A fixed count on a stretch that is not made of block sides: a clear input error, nothing written.
  const auto bad = test::run_autoblock("mesh '" + folder + "/poly/shape_0000.brep' --policy greedy --intervals 0,0,1,1=3 --out '" +
                                       folder + "/bad.msh'");
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.err, Contains("edge (0, 0)-(1, 1)"));
  CHECK_FALSE(std::filesystem::exists(folder + "/bad.msh"));
  // eval: a data set's figures, by the general engine (no minimum there).
  const auto eval = test::run_autoblock("eval '" + folder + "/poly' '" + folder + "/cham' --policy greedy --threads 2 --json '" +
                                        folder + "/eval.json'");
  INFO(eval.out << eval.err);
  CHECK(eval.exit_code == 0);
  const nlohmann::json figures = test::read_json(folder + "/eval.json");
  CHECK(figures["summary"]["general_faces"] == 3);
  CHECK(figures["summary"]["complete"] == 3);
  CHECK(figures["shapes"].size() == 3);
  CHECK(figures["shapes"][0]["engine"] == "general");
  // The lookahead agents' trained policies take general faces (issue 12); the paper's agent does not.
  const auto learned_eval = test::run_autoblock("eval '" + folder + "/poly' --policy sac-paper");
  CHECK(learned_eval.exit_code == 0);
  CHECK_THAT(learned_eval.out, Contains("sac-paper on 2 shapes (general engine)"));
  const auto learned = test::run_autoblock("decompose '" + folder + "/poly/shape_0000.brep' --policy sac-mesh");
  CHECK(learned.exit_code == 0);
  CHECK_THAT(learned.out, Contains("sac-mesh (general engine)"));
  const auto faithful = test::run_autoblock("decompose '" + folder + "/poly/shape_0000.brep' --policy sac-faithful");
  CHECK(faithful.exit_code == 2);
  CHECK_THAT(faithful.err, Contains("this face has edges at other angles"));
}
