#include <catch2/catch.hpp>

#include <chrono>
#include <cstdlib>
#include <set>
#include <thread>

#include "core/baselines/auto_policy.h"
#include "core/baselines/greedy_policy.h"
#include "core/baselines/optimal_search.h"
#include "core/env/decomposition.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

// A stand-in for the learned fallback: greedy under another name, counting its calls.
class NamedGreedy : public Policy {
 public:
  explicit NamedGreedy(int* calls, double sleep_seconds = 0.0) : calls_(calls), sleep_(sleep_seconds) {}
  std::string name() const override { return "stand-in"; }
  Action choose(const Episode& episode) override {
    if (calls_) ++*calls_;
    if (sleep_ > 0) std::this_thread::sleep_for(std::chrono::duration<double>(sleep_));
    return GreedyPolicy().choose(episode);
  }

 private:
  int* calls_;
  double sleep_;
};

EpisodeOptions mesh_options() {
  EpisodeOptions options;
  options.reward = RewardPreset::Mesh;
  return options;
}

}  // namespace

TEST_CASE("auto with time to spare is the exact search, and never makes its fallback", "[baselines][auto]") {
  GeneratorOptions generator;
  generator.holes = true;
  for (const GeneratedShape& shape : test::generated_shapes(20, 31, generator)) {
    const GridFace face = make_grid_face(shape.polygon);
    int made = 0;
    AutoPolicyOptions options;
    options.part_seconds = 60;
    options.search_seconds = 60;
    AutoPolicy policy(face.size, options, [&] {
      ++made;
      return std::make_unique<NamedGreedy>(nullptr);
    });
    const Decomposition d = decompose_face(face, policy, mesh_options());
    OptimalSearch search(face.size, 0, RewardPreset::Mesh);
    CHECK(d.complete());
    CHECK(d.total_return == Approx(search.value(face.whole)));
    CHECK(made == 0);
    CHECK_FALSE(d.time_capped);
    REQUIRE(d.decided_by.size() == d.cuts.size());
    for (const std::string& who : d.decided_by) CHECK(who == "optimal");
  }
}

TEST_CASE("auto hands a part to its fallback when the search runs out of time, and says so", "[baselines][auto]") {
  GeneratorOptions generator;
  generator.min_rects = 30;
  generator.max_rects = 40;
  const GridFace face = make_grid_face(test::generated_shapes(1, 3, generator)[0].polygon);
  int made = 0, calls = 0;
  AutoPolicyOptions options;
  options.part_seconds = 1e-9;  // the search never finishes a part it has not seen
  options.search_seconds = 1e-9;
  AutoPolicy policy(face.size, options, [&] {
    ++made;
    return std::make_unique<NamedGreedy>(&calls);
  });
  const Decomposition d = decompose_face(face, policy, mesh_options());
  CHECK(d.complete());
  CHECK(made == 1);  // made once, on first need
  CHECK(calls > 0);
  const std::set<std::string> deciders(d.decided_by.begin(), d.decided_by.end());
  CHECK(deciders.count("stand-in") == 1);
  CHECK_FALSE(d.time_capped);
}

TEST_CASE("auto's search budgets are counted in work: the same cuts by the same deciders on every run", "[baselines][auto]") {
  GeneratorOptions generator;
  generator.min_rects = 30;
  generator.max_rects = 40;
  generator.holes = true;
  const GridFace face = make_grid_face(test::generated_shapes(1, 17, generator)[0].polygon);
  OptimalSearch full(face.size, 0, RewardPreset::Mesh);
  full.value(face.whole);
  const double whole = static_cast<double>(full.work()) / kOptimalWorkPerSecond;  // in seconds of work
  AutoPolicyOptions options;
  options.part_seconds = 0.3 * whole;  // the face's first part runs out; its pieces may not
  options.search_seconds = 0.6 * whole;
  std::vector<std::string> first_deciders;
  std::vector<CutRecord> first_cuts;
  for (int run = 0; run < 3; ++run) {
    // A fallback slow enough that a wall-clock budget would run out at another cut each run.
    AutoPolicy policy(face.size, options, [] { return std::make_unique<NamedGreedy>(nullptr, 0.001 * (1 + std::rand() % 5)); });
    const Decomposition d = decompose_face(face, policy, mesh_options());
    REQUIRE(d.complete());
    const std::vector<CutRecord>& cuts = d.cuts;
    if (run == 0) {
      first_deciders = d.decided_by;
      first_cuts = cuts;
      const std::set<std::string> deciders(d.decided_by.begin(), d.decided_by.end());
      CHECK(deciders.count("stand-in") == 1);
      CHECK(deciders.count("optimal") == 1);
    }
    CHECK(d.decided_by == first_deciders);
    REQUIRE(cuts.size() == first_cuts.size());
    for (size_t k = 0; k < cuts.size(); ++k) {
      CHECK(cuts[k].part_id == first_cuts[k].part_id);
      CHECK(cuts[k].position.x == first_cuts[k].position.x);
      CHECK(cuts[k].position.y == first_cuts[k].position.y);
      CHECK(cuts[k].direction == first_cuts[k].direction);
    }
  }
}

TEST_CASE("auto without a fallback finishes greedily and names greedy", "[baselines][auto]") {
  const GridFace face = make_grid_face(test::generated_shapes(1, 5, {})[0].polygon);
  AutoPolicyOptions options;
  options.part_seconds = 1e-9;
  options.search_seconds = 1e-9;
  AutoPolicy policy(face.size, options, []() -> std::unique_ptr<Policy> { throw std::runtime_error("no runtime"); });
  const Decomposition d = decompose_face(face, policy, mesh_options());
  CHECK(d.complete());
  for (const std::string& who : d.decided_by) CHECK((who == "greedy" || who == "optimal"));
}

TEST_CASE("auto's time limit finishes every face with greedy", "[baselines][auto]") {
  GeneratorOptions generator;
  generator.holes = true;
  for (const GeneratedShape& shape : test::generated_shapes(10, 7, generator)) {
    const GridFace face = make_grid_face(shape.polygon);
    AutoPolicyOptions options;
    options.part_seconds = 0;  // no search: every cut goes to the slow fallback until the limit
    options.search_seconds = 0;
    options.total_seconds = 0.004;
    AutoPolicy policy(face.size, options, [] { return std::make_unique<NamedGreedy>(nullptr, 0.002); });
    const Decomposition d = decompose_face(face, policy, mesh_options());
    CHECK(d.complete());
    if (d.cuts.size() > 3) {
      CHECK(d.time_capped);
      CHECK(d.decided_by.back() == "greedy");
    }
  }
}

TEST_CASE("a time-limited policy is finished by greedy once its limit passes", "[baselines][auto]") {
  GeneratorOptions generator;
  generator.min_rects = 11;
  generator.max_rects = 20;
  const GridFace face = make_grid_face(test::generated_shapes(1, 9, generator)[0].polygon);
  int calls = 0;
  auto policy = time_limited(std::make_unique<NamedGreedy>(&calls, 0.003), 0.005);
  const Decomposition d = decompose_face(face, *policy);
  CHECK(d.complete());
  REQUIRE(d.cuts.size() > 3);
  CHECK(d.time_capped);
  CHECK(calls < static_cast<int>(d.cuts.size()));
  CHECK(d.decided_by.front() == "stand-in");
  CHECK(d.decided_by.back() == "greedy");
  CHECK(d.policy == "stand-in");

  // No limit: the policy itself.
  auto unlimited = time_limited(std::make_unique<NamedGreedy>(nullptr), 0);
  const Decomposition u = decompose_face(face, *unlimited);
  CHECK_FALSE(u.time_capped);
  for (const std::string& who : u.decided_by) CHECK(who == "stand-in");
}
