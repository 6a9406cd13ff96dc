// `autoblock generate`'s shape options: the grid and the side range, recorded in index.json.
#include <catch2/catch.hpp>

#include <filesystem>

#include <nlohmann/json.hpp>

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
