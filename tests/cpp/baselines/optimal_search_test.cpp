#include <catch2/catch.hpp>

#include "core/baselines/baseline_policy.h"
#include "core/baselines/optimal_search.h"
#include "core/env/decomposition.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("optimal agrees with a hand-worked example and beats greedy on it", "[baselines][optimal]") {
  // The U-shape (0,0) (3,0) (3,2) (2,2) (2,1) (1,1) (1,2) (0,2); face size 3, areas / 9.
  // Splitting lines: y = 1, x = 1, x = 2 (the others run along the boundary).
  //  y = 1: three rectangles 3x1, 1x1, 1x1                                   -> 9.8364021603
  //  x = 1: left 1x2 (A 2/9, R 2) and an L (A 3/9, 2x2 box, R 1), N_q = 1:
  //         3 (sqrt(2/5) - sqrt((2 (0.5/9)^2) / (5/9))) + 10/2 - 1
  //         = 3 (0.6324555320 - 0.1054092553) + 4                           =  5.5811388301
  //         then the L (A 3/9) cut into 2x1 and 1x1 (A 2/9 and 1/9):
  //         3 (0.6324555320 - sqrt((2 (0.5/9)^2) / (3/9))) + 10 - 1
  //         = 3 (0.6324555320 - 0.1360827635) + 9                           = 10.4891183054
  //         total                                                            = 16.0702571355
  //  x = 2: the mirror image of x = 1                                        = 16.0702571355
  // Optimal: 16.0702571355 with 3 blocks; greedy takes y = 1 (9.836 > 5.581) and stops at 9.836.
  const GridFace face = test::grid_face_of({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  OptimalSearch search(face.size, 0);
  CHECK(search.value(face.whole) == Approx(16.0702571355).epsilon(1e-10));

  auto optimal = make_baseline_policy("optimal", face.size, {});
  auto greedy = make_baseline_policy("greedy", face.size, {});
  const Decomposition best = decompose_face(face, *optimal);
  const Decomposition greedy_result = decompose_face(face, *greedy);
  CHECK(best.total_return == Approx(16.0702571355).epsilon(1e-10));
  CHECK(best.cuts.size() == 2);
  CHECK(greedy_result.total_return == Approx(9.8364021603).epsilon(1e-10));
  CHECK_FALSE(best.time_capped);
}

TEST_CASE("the optimal search's value is what its policy collects", "[baselines][optimal]") {
  GeneratorOptions options;
  options.holes = true;
  for (const GeneratedShape& shape : test::generated_shapes(30, 11, options)) {
    const GridFace face = make_grid_face(shape.polygon);
    OptimalSearch search(face.size, 0);
    auto policy = make_baseline_policy("optimal", face.size, {});
    CHECK(decompose_face(face, *policy).total_return == Approx(search.value(face.whole)));
  }
}

TEST_CASE("the optimal policy reports hitting its time limit and still finishes", "[baselines][optimal]") {
  GeneratorOptions options;
  options.min_rects = 30;
  options.max_rects = 40;
  const GeneratedShape shape = test::generated_shapes(1, 3, options)[0];
  const GridFace face = make_grid_face(shape.polygon);
  OptimalPolicy policy(face.size, 1e-6);
  const Decomposition d = decompose_face(face, policy);
  CHECK(d.time_capped);
  CHECK(d.complete());
}

TEST_CASE("optimal under the mesh preset prefers fewer, then fatter blocks", "[baselines][optimal]") {
  // U-shape: y = 1 leaves 3 blocks (3x1, 1x1, 1x1) for -2 - 0.5 ln 3 = -2.5493061443; x = 1 and
  // then the L's cut also end with 3 blocks but cost -1 - 0.5 ln 2 (1x2 block) - 1 - 0.5 ln 2
  // (2x1 and 1x1) = -2.6931471806. Optimal takes y = 1.
  const GridFace face = test::grid_face_of({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  OptimalSearch search(face.size, 0, RewardPreset::Mesh);
  CHECK(search.value(face.whole) == Approx(-2.5493061443));
  const AxisLine line = search.best_line(face.whole);
  CHECK(line.direction == CutDirection::Horizontal);
  CHECK(line.index == 1);
}

TEST_CASE("under the mesh preset optimal needs close to the minimum number of blocks", "[baselines][optimal]") {
  // Not a theorem (full cuts cannot always reach the minimum partition): a measured property of
  // the generator's shapes, checked loosely.
  int blocks = 0, minimum = 0;
  for (const GeneratedShape& shape : test::generated_shapes(100, 12, {})) {
    const GridFace face = make_grid_face(shape.polygon);
    BaselineOptions options;
    options.reward = RewardPreset::Mesh;
    auto policy = make_baseline_policy("optimal", face.size, options);
    EpisodeOptions episode;
    episode.reward = RewardPreset::Mesh;
    const Decomposition d = decompose_face(face, *policy, episode);
    blocks += static_cast<int>(d.blocks.size());
    minimum += d.min_blocks;
  }
  CHECK(blocks <= 1.05 * minimum);
}

TEST_CASE("the exact search's budget is counted in work: it stops at the same place on every run", "[baselines][optimal]") {
  GeneratorOptions options;
  options.min_rects = 30;
  options.max_rects = 40;
  options.holes = true;
  const GridFace face = make_grid_face(test::generated_shapes(1, 17, options)[0].polygon);
  OptimalSearch full(face.size, 0, RewardPreset::Mesh);
  const double value = full.value(face.whole);
  const long long work = full.work();
  REQUIRE(work > 1000);
  // A third of that budget: stopped, each time after the same work with the same values memoised.
  const double seconds = static_cast<double>(work) / 3.0 / kOptimalWorkPerSecond;
  long long stopped_at = -1;
  size_t memo = 0;
  for (int run = 0; run < 3; ++run) {
    OptimalSearch search(face.size, seconds, RewardPreset::Mesh);
    CHECK_THROWS_AS(search.value(face.whole), OptimalSearch::TimeLimit);
    CHECK(search.work() > std::llround(seconds * kOptimalWorkPerSecond));
    CHECK(search.work() < work);
    if (run == 0) {
      stopped_at = search.work();
      memo = search.memo_size();
    }
    CHECK(search.work() == stopped_at);
    CHECK(search.memo_size() == memo);
  }
  // Budget enough: the full search, its value and work.
  OptimalSearch enough(face.size, 1.01 * static_cast<double>(work) / kOptimalWorkPerSecond, RewardPreset::Mesh);
  CHECK(enough.value(face.whole) == Approx(value));
  CHECK(enough.work() == work);
}
