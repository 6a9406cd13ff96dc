// `autoblock generate`'s shape options: the grid and the side range, recorded in index.json; faces with
// arcs (--kind arcs).
#include <catch2/catch.hpp>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/geometry/occt_properties.h"
#include "core/io/input_face.h"
#include "support/run_command.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("autoblock generate draws thin-feature faces on a grid and records the options", "[cli]") {
  const std::string folder = test::temporary_folder("cli-generate");
  const auto r = test::run_autoblock("generate --count 4 --seed 8 --grid 32 --min-side 3 --max-side 18 --out '" +
                                     folder + "/thin'");
  REQUIRE(r.exit_code == 0);
  const nlohmann::json index = test::read_json(folder + "/thin/index.json");
  CHECK(index["generator"]["grid"] == 32);
  CHECK(index["generator"]["min_side"] == 3);
  CHECK(index["generator"]["max_side"] == 18);
  CHECK(index["shapes"].size() == 4);
  // Today's defaults stay: no grid, sides 2-12.
  REQUIRE(test::run_autoblock("generate --count 1 --seed 8 --out '" + folder + "/plain'").exit_code == 0);
  const nlohmann::json plain = test::read_json(folder + "/plain/index.json");
  CHECK(plain["generator"]["grid"] == 0);
  CHECK(plain["generator"]["min_side"] == 2);
  CHECK(plain["generator"]["max_side"] == 12);
}

TEST_CASE("autoblock generate refuses impossible side ranges and grids, writing nothing", "[cli][errors]") {
  const std::string folder = test::temporary_folder("cli-generate-bad");
  for (const std::string options : {"--grid 10 --max-side 18", "--min-side 5 --max-side 3", "--min-side 0",
                                    "--grid -1"}) {
    const auto r = test::run_autoblock("generate --count 2 --seed 1 " + options + " --out '" + folder + "/t'");
    INFO(options << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, StartsWith("error: "));
    CHECK(test::line_count(r.err) == 1);
    CHECK_FALSE(std::filesystem::exists(folder + "/t/index.json"));
  }
}

TEST_CASE("autoblock generate --kind arcs writes faces with arcs that the reader takes, the same from a seed",
          "[cli][arc]") {
  const std::string folder = test::temporary_folder("cli-generate-arcs");
  const auto r = test::run_autoblock("generate --kind arcs --count 10 --seed 12 --out '" + folder + "/a'");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json index = test::read_json(folder + "/a/index.json");
  CHECK(index["format"] == "autoblock-dataset");
  CHECK(index["generator"]["kind"] == "arcs");
  CHECK(index["generator"]["seed"] == 12);
  CHECK(index["generator"]["min_scale"] == Approx(0.1));
  CHECK(index["generator"]["max_scale"] == Approx(100.0));
  REQUIRE(index["shapes"].size() == 10);
  int with_holes = 0;
  for (const nlohmann::json& shape : index["shapes"]) {
    const std::string file = folder + "/a/" + shape["file"].get<std::string>();
    INFO(file << ": " << shape["name"]);
    CHECK(shape["arcs"].get<int>() > 0);
    with_holes += shape["holes"].get<int>() > 0;
    const InputFace face = load_input_face(file);
    CHECK(face.is_general());
    CHECK(face.arcs.arcs.size() > 0);
    CHECK(face.region.holes().size() == shape["holes"].get<size_t>());
    CHECK(occt_area(face.model) == Approx(shape["area"].get<double>()).epsilon(1e-9));
  }
  CHECK(with_holes > 0);
  CHECK(index["shapes"][0]["file"] == "shape_0000.brep");
  // The same seed, the same faces.
  REQUIRE(test::run_autoblock("generate --kind arcs --count 10 --seed 12 --out '" + folder + "/b'").exit_code == 0);
  const nlohmann::json again = test::read_json(folder + "/b/index.json");
  CHECK(again["shapes"] == index["shapes"]);
  // A narrow scale range: faces of about that size.
  REQUIRE(test::run_autoblock("generate --kind arcs --count 3 --seed 1 --min-scale 1000 --max-scale 1000 --out '" + folder +
                              "/big'").exit_code == 0);
  for (const nlohmann::json& shape : test::read_json(folder + "/big/index.json")["shapes"]) {
    CHECK(shape["area"].get<double>() > 1e6);
  }
  const auto bad = test::run_autoblock("generate --kind arcs --count 2 --seed 1 --min-scale 2 --max-scale 1 --out '" + folder + "/c'");
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.err, StartsWith("error: "));
  CHECK(test::line_count(bad.err) == 1);
  CHECK_FALSE(std::filesystem::exists(folder + "/c/index.json"));
}
