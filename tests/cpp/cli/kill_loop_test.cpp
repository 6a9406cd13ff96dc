// Faults lose nothing: `autoblock` processes writing every kind of output are SIGKILLed at random
// moments; afterwards every target is absent or the old file (when there was one), or a complete,
// valid file; never half-written. The kills are seeded; AUTOBLOCK_KILLS sets their number (40 by
// default; the figure in README's development section comes from AUTOBLOCK_KILLS=200).
//
// Temporary files: a kill between writing and renaming leaves TARGET.autoblock-tmp-PID-N.EXT
// (atomic_file.h); they are counted, and the next complete run of the same command must remove
// them all.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <thread>

#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <nlohmann/json.hpp>

#include "core/io/shape_file.h"
#include "support/mesh_readers.h"
#include "support/run_command.h"
#include "support/test_shapes.h"

extern char** environ;

using namespace autoblock;
namespace fs = std::filesystem;

namespace {

struct Writer {
  std::string name;
  std::vector<std::string> arguments;  // after the executable
  std::vector<std::string> targets;
  double seconds = 0.0;                // a complete run's wall time (measured)
};

// Starts the CLI with arguments, its output going nowhere. Returns its pid.
pid_t spawn_cli(const std::vector<std::string>& arguments) {
  std::vector<std::string> copy = arguments;
  std::string binary = AUTOBLOCK_CLI;
  std::vector<char*> argv{binary.data()};
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, AUTOBLOCK_CLI, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  REQUIRE(spawned == 0);
  return pid;
}

int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

// Runs the CLI with arguments; kills it after delay seconds (< 0: never). Returns the wait status.
int run_and_kill(const std::vector<std::string>& arguments, double delay) {
  const pid_t pid = spawn_cli(arguments);
  if (delay >= 0) {
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    ::kill(pid, SIGKILL);
  }
  return wait_for(pid);
}

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

int face_count(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  return faces.Extent();
}

// Empty when path holds a complete file of its kind; else what is wrong.
std::string check_complete(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  const std::string bytes = test::slurp_file(path);
  try {
    if (ext == ".brep" || ext == ".step") return face_count(read_shape_file(path)) > 0 ? "" : "no faces";
    if (ext == ".json") return nlohmann::json::parse(bytes).is_object() ? "" : "not an object";
    if (ext == ".svg") return ends_with(bytes, "</svg>\n") ? "" : "no </svg> at the end";
    if (ext == ".png") {
      const bool ok = bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0 && bytes.size() >= 12 &&
                      bytes.compare(bytes.size() - 8, 4, "IEND") == 0;
      return ok ? "" : "not a complete PNG";
    }
    if (ext == ".msh") return test::read_msh41(bytes).quads.empty() ? "no quads" : "";
    if (ext == ".vtu") return test::read_vtu(bytes).quads.empty() ? "no quads" : "";
    if (ext == ".inp") return test::read_inp(bytes).quads.empty() ? "no quads" : "";
    if (ext == ".csv") return bytes.rfind("episode", 0) == 0 ? "" : "no header";
    // Policy files and checkpoints are zip archives (LibTorch): complete when the end-of-central-
    // directory record is there.
    if (ext == ".pt" || ext == ".checkpoint") return bytes.find("PK\x05\x06") != std::string::npos ? "" : "no zip end record";
  } catch (const std::exception& e) {
    return e.what();
  }
  return "unknown kind";
}

int kills_wanted() {
  const char* text = std::getenv("AUTOBLOCK_KILLS");
  return text ? std::max(1, std::atoi(text)) : 40;
}

std::vector<std::string> leftovers(const std::string& folder) {
  std::vector<std::string> found;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().filename().string().find(".autoblock-tmp-") != std::string::npos) found.push_back(entry.path().string());
  }
  return found;
}

}  // namespace

TEST_CASE("outputs of autoblock processes killed at random moments are old, absent or complete", "[cli][atomic][kill]") {
  const std::string folder = test::temporary_folder("kill-loop");
  const std::string data = std::string(AUTOBLOCK_SOURCE_DIR) + "/models/data";
  const std::string face = data + "/test-holes/shape_0001.brep";
  const std::string out = folder + "/out";
  fs::create_directories(out);
  auto at = [&](const std::string& name) { return out + "/" + name; };
  std::vector<Writer> writers{
      {"decompose brep/json/svg",
       {"decompose", face, "--policy", "greedy", "--out", at("b.brep"), "--json", at("r.json"), "--picture", at("p.svg")},
       {at("b.brep"), at("r.json"), at("p.svg")}},
      {"decompose step/png", {"decompose", face, "--policy", "greedy", "--out", at("b.step"), "--picture", at("p.png")},
       {at("b.step"), at("p.png")}},
      {"mesh msh/json", {"mesh", face, "--policy", "greedy", "--out", at("m.msh"), "--json", at("m.json")},
       {at("m.msh"), at("m.json")}},
      {"mesh vtu", {"mesh", face, "--policy", "greedy", "--out", at("m.vtu")}, {at("m.vtu")}},
      {"mesh inp/png", {"mesh", face, "--policy", "greedy", "--out", at("m.inp"), "--picture", at("m.png")},
       {at("m.inp"), at("m.png")}},
      {"train policy/checkpoint/log/curves",
       {"train", "--train", data + "/test", "--test", data + "/test", "--episodes", "4", "--eval-every", "2", "--seed", "3",
        "--out", at("t.pt"), "--checkpoint", at("t.checkpoint"), "--log", at("t.csv"), "--curves", at("t.svg")},
       {at("t.pt"), at("t.checkpoint"), at("t.csv"), at("t.svg")}},
  };
  // A complete run of each writer: the old files, and how long a run takes.
  for (Writer& w : writers) {
    const auto start = std::chrono::steady_clock::now();
    const int status = run_and_kill(w.arguments, -1);
    w.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO(w.name);
    REQUIRE((WIFEXITED(status) && WEXITSTATUS(status) == 0));
    for (const std::string& t : w.targets) REQUIRE(check_complete(t).empty());
  }

  const int kills = kills_wanted();
  std::mt19937 random(20261130);
  int half_written = 0, absent = 0, complete = 0, finished = 0, temporary_seen = 0;
  for (int k = 0; k < kills; ++k) {
    const Writer& w = writers[static_cast<size_t>(k) % writers.size()];
    // Every other round of the writers starts without the old files: then a target may stay absent.
    const bool fresh = (k / static_cast<int>(writers.size())) % 2 == 1;
    if (fresh) {
      for (const std::string& t : w.targets) fs::remove(t);
    }
    std::vector<bool> existed;
    for (const std::string& t : w.targets) existed.push_back(fs::exists(t));
    const double delay = std::uniform_real_distribution<double>(0.0, 1.1 * w.seconds)(random);
    const int status = run_and_kill(w.arguments, delay);
    finished += WIFEXITED(status);
    for (size_t i = 0; i < w.targets.size(); ++i) {
      const std::string& t = w.targets[i];
      if (!fs::exists(t)) {
        INFO(w.name << ": " << t << " vanished although it existed before the run");
        CHECK_FALSE(existed[i]);
        ++absent;
        continue;
      }
      const std::string problem = check_complete(t);
      INFO(w.name << " killed after " << delay << " s: " << t << ": " << problem);
      CHECK(problem.empty());
      if (problem.empty()) ++complete; else ++half_written;
    }
    temporary_seen += static_cast<int>(leftovers(out).size()) > 0;
  }
  WARN(kills << " kills (" << finished << " runs finished first): " << complete << " targets complete, " << absent
             << " absent, " << half_written << " half-written; temporary files left after " << temporary_seen
             << " of the kills");
  CHECK(half_written == 0);

  // The next complete run of each writer removes the temporary files the killed ones left.
  for (const Writer& w : writers) REQUIRE(WIFEXITED(run_and_kill(w.arguments, -1)));
  CHECK(leftovers(out).empty());
}

TEST_CASE("autoblock train --resume continues from the checkpoint after a SIGKILL", "[cli][atomic][kill][train]") {
  const std::string folder = test::temporary_folder("kill-resume");
  const std::string data = std::string(AUTOBLOCK_SOURCE_DIR) + "/models/data";
  const std::string checkpoint = folder + "/t.checkpoint";
  const std::vector<std::string> arguments{"train", "--train", data + "/test", "--test", data + "/test", "--episodes", "40",
                                           "--eval-every", "2", "--seed", "5", "--out", folder + "/t.pt",
                                           "--checkpoint", checkpoint, "--log", folder + "/t.csv", "--curves",
                                           folder + "/t.svg"};
  // Kill the run once its first checkpoint exists (polling), then a little later.
  const pid_t pid = spawn_cli(arguments);
  const auto start = std::chrono::steady_clock::now();
  while (!fs::exists(checkpoint) && std::chrono::steady_clock::now() - start < std::chrono::seconds(120)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(pid, SIGKILL);
  const int status = wait_for(pid);
  REQUIRE(fs::exists(checkpoint));
  REQUIRE(check_complete(checkpoint).empty());
  INFO("the run finished before the kill: the test proves nothing then");
  REQUIRE(WIFSIGNALED(status));
  REQUIRE_FALSE(fs::exists(folder + "/t.pt"));

  std::string resume;
  for (const std::string& a : arguments) resume += "'" + a + "' ";
  const auto r = test::run_autoblock(resume + "--resume '" + checkpoint + "'");
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(check_complete(folder + "/t.pt").empty());
  // The log holds every episode once, 1..40, in order: the resumed run continued where the
  // checkpoint left off (episodes after the checkpoint that the kill lost are redone, not doubled).
  const std::string log = test::slurp_file(folder + "/t.csv");
  int rows = 0, last = 0;
  bool in_order = true;
  size_t line_start = log.find('\n') + 1;
  while (line_start < log.size()) {
    const size_t end = log.find('\n', line_start);
    const int episode = std::atoi(log.substr(line_start, end - line_start).c_str());
    in_order = in_order && episode == last + 1;
    last = episode;
    ++rows;
    line_start = end == std::string::npos ? log.size() : end + 1;
  }
  CHECK(in_order);
  CHECK(rows == 40);
  CHECK(leftovers(folder).empty());
}
