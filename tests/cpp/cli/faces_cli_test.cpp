// `autoblock faces FILE` and `--face N` on the commands that read a face.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/io/face_selection.h"
#include "core/io/shape_file.h"
#include "support/bad_shapes.h"
#include "support/run_command.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

void check_input_error(const test::CommandResult& r) {
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, StartsWith("error: "));
  CHECK(test::line_count(r.err) == 1);
  CHECK(r.out.empty());
}

struct StepPart {
  std::string folder, path;
  int top = 0, cylinder = 0, side = 0;
};

// The test part as a STEP file, and the numbers of its top face, its cylinder's side and a vertical face.
StepPart step_part() {
  StepPart part;
  part.folder = test::temporary_folder("faces-cli");
  part.path = part.folder + "/part.step";
  write_shape_file(part.path, test::part_with_many_faces());
  for (const FaceSummary& f : list_faces(read_shape_file(part.path))) {
    if (f.problem.empty() && f.normal[2] > 0.5 && f.area > 50) part.top = f.number;  // the slab's, not the cylinder's disk
    if (f.surface == "cylinder") part.cylinder = f.number;
    if (f.planar && f.normal[2] == 0 && part.side == 0) part.side = f.number;
  }
  REQUIRE(part.top > 0);
  REQUIRE(part.cylinder > 0);
  REQUIRE(part.side > 0);
  return part;
}

}  // namespace

TEST_CASE("autoblock faces lists a part's faces with number, surface, area and normal", "[cli][faces]") {
  const StepPart part = step_part();
  const auto r = test::run_autoblock("faces '" + part.path + "'");
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, StartsWith(part.path + ": 15 faces; AutoBlock can use 14 (choose with --face N)\n"));
  CHECK(test::line_count(r.out) == 2 + 15);
  std::istringstream lines(r.out);
  std::string line;
  std::getline(lines, line);
  std::getline(lines, line);  // the header
  int rows = 0;
  while (std::getline(lines, line)) {
    ++rows;
    std::istringstream row(line);
    int number = 0;
    std::string surface;
    row >> number >> surface;
    CHECK(number == rows);
    if (number == part.top) {
      CHECK(surface == "plane");
      CHECK_THAT(line, Contains(" 52 ") && Contains("(0, 0, 1)") && Contains("yes"));
    }
    if (number == part.cylinder) {
      CHECK(surface == "cylinder");
      CHECK_THAT(line, Contains(" - ") && Contains("no: the face is not planar"));
    }
    CHECK_THAT(line, !Contains("e+") && !Contains("e-"));
  }
  CHECK(rows == 15);
  check_input_error(test::run_autoblock("faces '" + part.folder + "/missing.step'"));
}

TEST_CASE("the option --face N picks a face of a STEP part: good, missing, out of range, curved", "[cli][faces][errors]") {
  const StepPart part = step_part();
  const std::string file = "'" + part.path + "'";
  const std::string top = std::to_string(part.top);
  SECTION("good: decompose, mesh and eval take the top face") {
    const std::string json = part.folder + "/r.json";
    const auto d = test::run_autoblock("decompose " + file + " --face " + top + " --policy greedy --json '" + json + "'");
    INFO(d.err);
    REQUIRE(d.exit_code == 0);
    const auto report = test::read_json(json);
    CHECK(report["face"]["z"].get<double>() == Approx(3.0));
    CHECK(report["complete"].get<bool>());
    const auto m = test::run_autoblock("mesh " + file + " --face " + top + " --policy greedy");
    INFO(m.err);
    CHECK(m.exit_code == 0);
    const auto e = test::run_autoblock("eval " + file + " --face " + top + " --policy greedy");
    INFO(e.err);
    CHECK(e.exit_code == 0);
  }
  SECTION("missing: one line that says --face and autoblock faces") {
    for (const std::string command : {"decompose ", "mesh ", "eval "}) {
      const auto r = test::run_autoblock(command + file + " --policy greedy");
      INFO(command << r.err);
      check_input_error(r);
      CHECK(r.err == "error: " + part.path + ": the file holds a compound with 15 faces; choose one with --face N "
                     "(`autoblock faces " + part.path + "` lists them)\n");
    }
  }
  SECTION("out of range, zero, not a number") {
    const auto r = test::run_autoblock("decompose " + file + " --face 16");
    INFO(r.err);
    check_input_error(r);
    CHECK_THAT(r.err, Contains("has no face 16: it holds a compound with 15 faces (faces 1 to 15)"));
    const auto zero = test::run_autoblock("decompose " + file + " --face 0");
    check_input_error(zero);
    CHECK_THAT(zero.err, Contains("faces are numbered from 1 (Face1, Face2, ...), not 0"));
    check_input_error(test::run_autoblock("decompose " + file + " --face two"));
  }
  SECTION("a curved face is named; a side face is meshed in its own frame, written where it is") {
    const auto r = test::run_autoblock("decompose " + file + " --face " + std::to_string(part.cylinder));
    INFO(r.err);
    check_input_error(r);
    CHECK(r.err == "error: " + part.path + " (Face" + std::to_string(part.cylinder) +
                       "): the face is not planar: its surface is a cylinder\n");
    const std::string inp = part.folder + "/side.inp";
    const auto s = test::run_autoblock("mesh " + file + " --face " + std::to_string(part.side) + " --policy greedy --out '" + inp + "'");
    INFO(s.err);
    REQUIRE(s.exit_code == 0);
    // Every node lies in the side's plane: along the side's normal (X or Y) the coordinate is constant.
    std::ifstream in(inp);
    std::string line;
    bool nodes = false;
    double low[3] = {1e300, 1e300, 1e300}, high[3] = {-1e300, -1e300, -1e300};
    int count = 0;
    while (std::getline(in, line)) {
      if (!line.empty() && line[0] == '*') {
        nodes = line.rfind("*NODE", 0) == 0;
        continue;
      }
      if (!nodes) continue;
      std::replace(line.begin(), line.end(), ',', ' ');
      std::istringstream row(line);
      int id = 0;
      double p[3];
      row >> id >> p[0] >> p[1] >> p[2];
      for (int k = 0; k < 3; ++k) low[k] = std::min(low[k], p[k]), high[k] = std::max(high[k], p[k]);
      ++count;
    }
    CHECK(count > 4);
    const int flat = (high[0] - low[0] < 1e-6 ? 1 : 0) + (high[1] - low[1] < 1e-6 ? 1 : 0);
    CHECK(flat == 1);
    CHECK(high[2] - low[2] > 0.5);  // the side stands up along Z
  }
}
