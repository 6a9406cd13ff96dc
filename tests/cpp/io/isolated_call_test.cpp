#include <catch2/catch.hpp>

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <stdexcept>

#include "core/common/error.h"
#include "core/io/isolated_call.h"

using namespace autoblock;
using Catch::Matchers::Contains;

namespace {
double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

TEST_CASE("run_isolated passes work's text and messages back", "[io][isolated]") {
  const std::string big(3 << 20, 'x');  // larger than a pipe's buffer
  CHECK(run_isolated([&] { return big; }, "input", 10) == big);
  CHECK(run_isolated([] { return std::string(); }, "input", 10).empty());
  REQUIRE_THROWS_WITH(run_isolated([]() -> std::string { throw InputError("f.brep: bad count"); }, "f.brep", 10),
                      Contains("f.brep: bad count"));
  REQUIRE_THROWS_AS(run_isolated([]() -> std::string { throw std::runtime_error("x"); }, "f.brep", 10), InputError);
  // Budget 0: in this process, failures still become InputError.
  REQUIRE_THROWS_AS(run_isolated([]() -> std::string { throw std::runtime_error("x"); }, "f.brep", 0), InputError);
  CHECK(run_isolated([] { return std::string("here"); }, "input", 0) == "here");
}

TEST_CASE("run_isolated stops a child that loops for ever, and survives one that crashes", "[io][isolated][errors]") {
  const pid_t me = ::getpid();
  auto start = std::chrono::steady_clock::now();
  REQUIRE_THROWS_WITH(run_isolated(
                          []() -> std::string {
                            for (volatile unsigned long i = 0;; i = i + 1) {
                            }
                          },
                          "loop.brep", 0.5),
                      Contains("loop.brep: reading took longer than 0.5 s and was stopped"));
  CHECK(seconds_since(start) < 10);  // generous: the budget is 0.5 s, the machine may be busy
  REQUIRE_THROWS_WITH(run_isolated(
                          []() -> std::string {
                            std::abort();
                          },
                          "abort.brep", 10),
                      Contains("abort.brep: the reader crashed on it (signal 6"));
  // An access violation: OpenCASCADE's handler turns it into an exception in the child, or the
  // child dies of it; either way an InputError here.
  REQUIRE_THROWS_AS(run_isolated(
                        []() -> std::string {
                          volatile int* nothing = nullptr;
                          *nothing = 1;
                          return "unreachable";
                        },
                        "segv.brep", 10),
                    InputError);
  CHECK(::getpid() == me);
}

TEST_CASE("read_budget_seconds reads AUTOBLOCK_READ_TIMEOUT", "[io][isolated]") {
  ::setenv("AUTOBLOCK_READ_TIMEOUT", "2.5", 1);
  CHECK(read_budget_seconds() == 2.5);
  ::setenv("AUTOBLOCK_READ_TIMEOUT", "0", 1);
  CHECK(read_budget_seconds() == 0.0);
  ::setenv("AUTOBLOCK_READ_TIMEOUT", "soon", 1);
  CHECK(read_budget_seconds() == 30.0);
  ::unsetenv("AUTOBLOCK_READ_TIMEOUT");
  CHECK(read_budget_seconds() == 30.0);
}
