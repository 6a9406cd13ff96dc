// The `autoblock` command line as a contract: exit codes, one-line errors, report fields.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <nlohmann/json.hpp>

#include "core/io/shape_file.h"
#include "support/bad_shapes.h"
#include "support/run_command.h"
#include "support/test_shapes.h"

using namespace autoblock;
using test::read_json;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {
void check_usage_error(const test::CommandResult& r) {
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, StartsWith("error: "));
  CHECK(test::line_count(r.err) == 1);
}
}  // namespace

TEST_CASE("autoblock --help works for every command", "[cli]") {
  for (const std::string command : {"", "generate", "decompose", "eval", "mesh", "faces", "combine"}) {
    const auto r = test::run_autoblock(command + " --help");
    INFO(command);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Contains("Usage") || Contains("USAGE") || Contains("usage"));
  }
}

TEST_CASE("autoblock generate, decompose and eval work end to end", "[cli]") {
  const std::string folder = test::temporary_folder("cli");
  const auto gen = test::run_autoblock("generate --count 6 --seed 3 --holes --out '" + folder + "/set'");
  REQUIRE(gen.exit_code == 0);
  const nlohmann::json index = read_json(folder + "/set/index.json");
  REQUIRE(index["shapes"].size() == 6);
  CHECK(index["generator"]["seed"] == 3);
  CHECK(index["shapes"][0]["holes"].get<int>() >= 1);

  const std::string shape = folder + "/set/" + index["shapes"][0]["file"].get<std::string>();
  for (const std::string policy : {"random", "random-split", "greedy", "optimal"}) {
    INFO(policy);
    const auto r = test::run_autoblock("decompose '" + shape + "' --policy " + policy + " --seed 5 --out '" + folder +
                                       "/b.brep' --json '" + folder + "/r.json' --picture '" + folder + "/p.svg'");
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());
    const nlohmann::json report = read_json(folder + "/r.json");
    for (const char* key : {"input", "policy", "blocks", "cuts", "return", "n_blocks", "min_blocks", "complete",
                            "truncated", "seconds"}) {
      CHECK(report.contains(key));
    }
    CHECK(report["policy"] == policy);
    CHECK(report["complete"] == true);
    CHECK(report["n_blocks"] == report["blocks"].size());
    CHECK(report["min_blocks"].get<int>() <= report["n_blocks"].get<int>());
    double sum = 0;
    for (const auto& cut : report["cuts"]) {
      sum += cut["reward"].get<double>();
      CHECK((cut["direction"] == "horizontal" || cut["direction"] == "vertical"));
      CHECK(cut["vertex"].size() == 2);
      CHECK(cut["n_parts"].get<int>() >= 1);
    }
    CHECK(report["return"].get<double>() == Approx(sum));
    for (const auto& block : report["blocks"]) {
      REQUIRE(block.size() == 4);
      double twice_area = 0;  // counter-clockwise: positive shoelace area
      for (int k = 0; k < 4; ++k) {
        twice_area += block[k][0].get<double>() * block[(k + 1) % 4][1].get<double>() -
                      block[(k + 1) % 4][0].get<double>() * block[k][1].get<double>();
      }
      CHECK(twice_area > 0);
    }
    const TopoDS_Shape blocks = read_shape_file(folder + "/b.brep");
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(blocks, TopAbs_FACE, faces);
    CHECK(faces.Extent() == report["n_blocks"].get<int>());
    CHECK(std::filesystem::file_size(folder + "/p.svg") > 100);
  }

  const auto eval = test::run_autoblock("eval '" + folder + "/set' --policy greedy --json '" + folder + "/e.json'");
  REQUIRE(eval.exit_code == 0);
  const nlohmann::json summary = read_json(folder + "/e.json");
  CHECK(summary["shapes"].size() == 6);
  CHECK(summary["summary"]["completion_rate"] == 1.0);
  CHECK(summary["summary"]["return"].contains("median"));
}

TEST_CASE("autoblock: every bad input gets exit 2 and a one-line error", "[cli][errors]") {
  const std::string folder = test::temporary_folder("cli-bad");
  for (const test::BadShape& bad : test::bad_shapes()) {
    if (bad.name == "solid") continue;  // a box is a swept solid: its cap is decomposed (solid_cli_test.cpp)
    const std::string path = folder + "/" + bad.name + ".brep";
    write_shape_file(path, bad.shape);
    const auto r = test::run_autoblock("decompose '" + path + "' --json '" + folder + "/r.json'");
    INFO(bad.name << ": " << r.err);
    check_usage_error(r);
    CHECK_THAT(r.err, Contains(bad.expected));
    CHECK_FALSE(std::filesystem::exists(folder + "/r.json"));  // nothing half-written
  }
  std::ofstream(folder + "/empty.brep").close();
  std::ofstream(folder + "/garbage.brep") << "not a shape at all\n";
  std::ofstream(folder + "/garbage.step") << "ISO-10303-21;\nnonsense\n";
  const std::vector<std::pair<std::string, std::string>> files{{"missing.brep", "no such file"},
                                                               {"empty.brep", "the file is empty"},
                                                               {"garbage.brep", "not a readable BREP file"},
                                                               {"garbage.step", "not a readable STEP file"}};
  for (const auto& [name, expected] : files) {
    const auto r = test::run_autoblock("decompose '" + folder + "/" + name + "'");
    INFO(name);
    check_usage_error(r);
    CHECK_THAT(r.err, Contains(expected));
  }
}

TEST_CASE("autoblock: usage errors get exit 2 and a one-line error", "[cli][errors]") {
  const std::string folder = test::temporary_folder("cli-usage");
  REQUIRE(test::run_autoblock("generate --count 2 --seed 1 --out '" + folder + "/s'").exit_code == 0);
  const std::string shape = folder + "/s/shape_0000.brep";
  const std::vector<std::string> cases{std::string(""), std::string("frobnicate"), std::string("generate --count 0 --seed 1 --out x"),
        std::string("generate --seed 1 --out x"), std::string("generate --count 2 --seed 1 --min-rects 5 --max-rects 2 --out '") + folder + "/t'",
        "decompose '" + shape + "' --policy nonsense", "decompose '" + shape + "' --out blocks.txt",
        "decompose '" + shape + "' --max-steps -3", "decompose", "eval '" + folder + "/nowhere'",
        "eval '" + folder + "'"};
  for (const std::string& arguments : cases) {
    const auto r = test::run_autoblock(arguments);
    INFO(arguments << ": " << r.err);
    check_usage_error(r);
  }
}

TEST_CASE("autoblock train: bad options and data get exit 2 and a one-line error", "[cli][errors][train]") {
  // Every case is refused before training starts, so nothing is written.
  const std::string folder = test::temporary_folder("cli-train");
  REQUIRE(test::run_autoblock("generate --count 2 --seed 1 --out '" + folder + "/s'").exit_code == 0);
  const std::string data = "--train '" + folder + "/s' --test '" + folder + "/s' --out '" + folder + "/p.pt' ";
  const std::vector<std::string> cases{"train", "train --train '" + folder + "/nowhere' --test '" + folder + "/s'",
                                       "train " + data + "--deploy-views 9", "train " + data + "--weight-average 1",
                                       "train " + data + "--lr-final 0", "train " + data + "--resume '" + folder + "/none.pt'",
                                       "train " + data + "--curves '" + folder + "/c.txt'",
                                       "train " + data + "--set no_such_field=1", "train " + data + "--set gamma=2",
                                       "train " + data + "--set gamma",
                                       "train " + data + "--resume '" + folder + "/p.pt' --set gamma=0.5",
                                       "train --train '" + folder + "/s' --test '" + folder + "/s' --out '" + folder +
                                           "/no/such/p.pt' --episodes 1",
                                       "train " + data + "--init no-such-policy",
                                       "train " + data + "--init sac-faithful"};
  for (const std::string& arguments : cases) {
    const auto r = test::run_autoblock(arguments);
    INFO(arguments << ": " << r.err);
    check_usage_error(r);
  }
  CHECK_FALSE(std::filesystem::exists(folder + "/p.pt"));
}

TEST_CASE("autoblock combine: one policy file, one network per kind of face, bad requests write nothing",
          "[cli][combine][train]") {
  const std::string folder = test::temporary_folder("cli-combine");
  const auto r = test::run_autoblock("combine --grid sac-mesh --general sac-mesh --out '" + folder + "/both.pt'");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Contains("rectilinear faces by sac-mesh's network") && Contains("general faces by sac-mesh's"));
  // Both kinds of face decompose with it, as with the network it was made of (here the same twice).
  REQUIRE(test::run_autoblock("generate --count 1 --seed 4 --out '" + folder + "/grid'").exit_code == 0);
  REQUIRE(test::run_autoblock("generate --kind polygon --count 1 --seed 4 --out '" + folder + "/general'").exit_code == 0);
  for (const std::string face : {"grid", "general"}) {
    INFO(face);
    nlohmann::json reports[2];
    int k = 0;
    for (const std::string& policy : {std::string("sac-mesh"), "'" + folder + "/both.pt'"}) {
      const auto d = test::run_autoblock("decompose '" + folder + "/" + face + "/shape_0000.brep' --policy " + policy +
                                         " --json '" + folder + "/r.json'");
      INFO(d.err);
      REQUIRE(d.exit_code == 0);
      reports[k++] = read_json(folder + "/r.json");
    }
    CHECK(reports[0]["n_blocks"] == reports[1]["n_blocks"]);
    CHECK(reports[0]["return"] == reports[1]["return"]);
  }
  const std::vector<std::string> cases{
      "combine --grid sac-mesh --general sac-paper --out '" + folder + "/x.pt'",  // two reward presets
      "combine --grid sac-mesh --general '" + folder + "/none.pt' --out '" + folder + "/x.pt'",
      "combine --grid no-such-policy --general sac-mesh --out '" + folder + "/x.pt'",
      "combine --grid sac-mesh --general sac-mesh --out '" + folder + "/no/such/x.pt'",
      "combine --grid sac-mesh --out '" + folder + "/x.pt'"};
  for (const std::string& arguments : cases) {
    const auto e = test::run_autoblock(arguments);
    INFO(arguments << ": " << e.err);
    check_usage_error(e);
  }
  CHECK_FALSE(std::filesystem::exists(folder + "/x.pt"));
}

TEST_CASE("autoblock loads LibTorch only for a learned policy, STEP only for STEP files (the loader's own record)", "[cli][startup]") {
  const std::string folder = test::temporary_folder("cli-startup");
  REQUIRE(test::run_autoblock("generate --count 1 --seed 8 --out '" + folder + "/set'").exit_code == 0);
  const std::string shape = folder + "/set/shape_0000.brep";
  // LD_DEBUG=files makes the dynamic loader name every library it loads (dlopen included) on stderr.
  const auto loaded = [](const std::string& arguments) {
    const auto r = test::run_shell("LD_DEBUG=files '" AUTOBLOCK_CLI "' " + arguments);
    INFO(arguments << "\n" << r.err.substr(0, 2000));
    REQUIRE(r.exit_code == 0);
    return r.err;
  };
  for (const std::string& arguments :
       {std::string("--help"), "decompose '" + shape + "' --policy greedy", "decompose '" + shape + "' --policy optimal",
        "decompose '" + shape + "'", "mesh '" + shape + "' --policy auto --out '" + folder + "/m.msh'"}) {
    INFO(arguments);
    const std::string err = loaded(arguments);
    CHECK_THAT(err, Contains("libTK"));  // the check sees what was loaded ...
    CHECK_THAT(err, !Contains("libtorch") && !Contains("libautoblock_learn"));
    CHECK_THAT(err, !Contains("libTKSTEP") && !Contains("libautoblock_step"));
  }
  // Writing a STEP file loads the translator; reading one loads it in the reading process (a child,
  // whose output goes nowhere), and the face read meshes.
  CHECK_THAT(loaded("decompose '" + shape + "' --policy greedy --out '" + folder + "/b.step'"),
             Contains("libautoblock_step") && Contains("libTKSTEP"));
  const auto read = test::run_autoblock("mesh '" + folder + "/b.step' --face 1 --policy greedy --out '" + folder + "/m.msh'");
  CHECK(read.exit_code == 0);
  CHECK(std::filesystem::exists(folder + "/m.msh"));
  // ... and a learned policy does load the runtime.
  CHECK_THAT(loaded("decompose '" + shape + "' --policy sac-mesh"), Contains("libautoblock_learn") && Contains("libtorch"));
}

TEST_CASE("autoblock decompose: auto reports who decided each cut", "[cli][auto]") {
  const std::string folder = test::temporary_folder("cli-auto");
  REQUIRE(test::run_autoblock("generate --count 3 --seed 12 --holes --out '" + folder + "/set'").exit_code == 0);
  for (int k = 0; k < 3; ++k) {
    const std::string shape = folder + "/set/shape_000" + std::to_string(k) + ".brep";
    const auto r = test::run_autoblock("decompose '" + shape + "' --json '" + folder + "/r.json'");
    REQUIRE(r.exit_code == 0);
    const nlohmann::json report = read_json(folder + "/r.json");
    CHECK(report["policy"] == "auto");
    CHECK(report["reward"] == "mesh");
    CHECK(report["complete"] == true);
    int counted = 0;
    for (const auto& cut : report["cuts"]) {
      CHECK(cut["decided_by"] == "optimal");  // small faces: the exact search finishes in time
      ++counted;
    }
    CHECK(report["decided_by"]["optimal"] == counted);
  }
}
