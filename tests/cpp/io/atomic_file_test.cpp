#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "core/io/atomic_file.h"
#include "core/io/text_file.h"
#include "support/mesh_readers.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {
size_t files_in(const std::string& folder) {
  size_t n = 0;
  for (const auto& entry : fs::directory_iterator(folder)) n += entry.is_regular_file();
  return n;
}
// The pid of a process that has finished and been reaped.
pid_t finished_pid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}
}  // namespace

TEST_CASE("write_file_atomically replaces the target and leaves nothing else", "[io][atomic]") {
  const std::string folder = test::temporary_folder("atomic");
  const std::string target = folder + "/report.json";
  write_text_file(target, "old\n");
  write_text_file(target, "new\n");
  CHECK(test::slurp_file(target) == "new\n");
  CHECK(files_in(folder) == 1);
}

TEST_CASE("a failed or throwing writer keeps the old file and removes its temporary file", "[io][atomic][errors]") {
  const std::string folder = test::temporary_folder("atomic-fail");
  const std::string target = folder + "/blocks.brep";
  write_text_file(target, "old\n");
  std::string seen;
  REQUIRE_THROWS_WITH(write_file_atomically(target,
                                            [&](const std::string& temporary) {
                                              seen = temporary;
                                              std::ofstream(temporary) << "half";
                                              return false;
                                            }),
                      Contains("cannot write the file"));
  CHECK(fs::path(seen).parent_path() == fs::path(target).parent_path());
  CHECK(fs::path(seen).extension() == ".brep");  // writers that choose a format by extension see the target's
  REQUIRE_THROWS_AS(write_file_atomically(target,
                                          [&](const std::string& temporary) -> bool {
                                            std::ofstream(temporary) << "half";
                                            throw std::runtime_error("disk on fire");
                                          }),
                    std::runtime_error);
  CHECK(test::slurp_file(target) == "old\n");
  CHECK(files_in(folder) == 1);
  REQUIRE_THROWS_WITH(write_text_file(folder + "/no/such/folder/x.txt", "x"), Contains("does not exist"));
  REQUIRE_THROWS_WITH(write_text_file(folder, "x"), Contains("is a directory"));
  CHECK(files_in(folder) == 1);
}

TEST_CASE("temporary files of writers that died are removed by the next write of the target", "[io][atomic]") {
  const std::string folder = test::temporary_folder("atomic-stale");
  const std::string target = folder + "/mesh.msh";
  // What a SIGKILL between writing and renaming leaves behind, and a live writer's file.
  const std::string dead = target + ".autoblock-tmp-" + std::to_string(finished_pid()) + "-7.msh";
  const std::string live = target + ".autoblock-tmp-" + std::to_string(::getpid()) + "-8.msh";
  const std::string other = folder + "/other.msh.autoblock-tmp-" + std::to_string(finished_pid()) + "-9.msh";
  for (const std::string& path : {dead, live, other}) std::ofstream(path) << "partial";
  CHECK(stale_temporary_files(target) == std::vector<std::string>{dead});
  write_text_file(target, "complete\n");
  CHECK_FALSE(fs::exists(dead));
  CHECK(fs::exists(live));   // a writer still running is left alone
  CHECK(fs::exists(other));  // another target's leftovers wait for that target's next write
  CHECK(test::slurp_file(target) == "complete\n");
}
