// Property tests over hundreds of generated shapes, with and without holes, for every policy.
#include <catch2/catch.hpp>

#include <map>

#include "core/baselines/baseline_policy.h"
#include "core/env/decomposition.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

// Every block is a grid-aligned rectangle; together they cover each cell of the face exactly once
// and nothing outside it (so: rectangles, no overlap, union = face, areas sum to the face's).
void check_partition(const GridFace& face, const Decomposition& d) {
  const Grid& grid = *face.grid;
  std::vector<int> cover(static_cast<size_t>(grid.columns() * grid.rows()), 0);
  double area = 0;
  for (const Box& b : d.blocks) {
    REQUIRE(b.width() > 0);
    REQUIRE(b.height() > 0);
    area += b.area();
    const int i0 = static_cast<int>(std::lower_bound(grid.xs.begin(), grid.xs.end(), b.xmin) - grid.xs.begin());
    const int i1 = static_cast<int>(std::lower_bound(grid.xs.begin(), grid.xs.end(), b.xmax) - grid.xs.begin());
    const int j0 = static_cast<int>(std::lower_bound(grid.ys.begin(), grid.ys.end(), b.ymin) - grid.ys.begin());
    const int j1 = static_cast<int>(std::lower_bound(grid.ys.begin(), grid.ys.end(), b.ymax) - grid.ys.begin());
    REQUIRE(grid.xs[static_cast<size_t>(i0)] == b.xmin);
    REQUIRE(grid.xs[static_cast<size_t>(i1)] == b.xmax);
    REQUIRE(grid.ys[static_cast<size_t>(j0)] == b.ymin);
    REQUIRE(grid.ys[static_cast<size_t>(j1)] == b.ymax);
    for (int j = j0; j < j1; ++j) {
      for (int i = i0; i < i1; ++i) {
        REQUIRE(face.whole.contains(i, j));  // inside the face
        ++cover[static_cast<size_t>(j * grid.columns() + i)];
      }
    }
  }
  for (int j = 0; j < grid.rows(); ++j) {
    for (int i = 0; i < grid.columns(); ++i) {
      REQUIRE(cover[static_cast<size_t>(j * grid.columns() + i)] == (face.whole.contains(i, j) ? 1 : 0));
    }
  }
  CHECK(area == Approx(face.whole.area()));
  CHECK(static_cast<int>(d.blocks.size()) >= d.min_blocks);
}

void check_policies(int count, std::uint64_t seed, bool holes) {
  GeneratorOptions options;
  options.holes = holes;
  const auto shapes = test::generated_shapes(count, seed, options);
  for (size_t s = 0; s < shapes.size(); ++s) {
    const GridFace face = make_grid_face(shapes[s].polygon);
    std::map<std::string, double> returns;
    for (const std::string& name : baseline_names()) {
      BaselineOptions baseline;
      baseline.seed = s;
      baseline.optimal_seconds = 0;  // exact
      auto policy = make_baseline_policy(name, face.size, baseline);
      const Decomposition d = decompose_face(face, *policy);
      INFO("shape " << s << ", policy " << name);
      REQUIRE(d.complete());
      check_partition(face, d);
      double sum = 0;
      for (const CutRecord& c : d.cuts) sum += c.reward;
      CHECK(d.total_return == Approx(sum));
      returns[name] = d.total_return;
    }
    INFO("shape " << s);
    CHECK(returns["optimal"] >= returns["greedy"] - 1e-9);
    CHECK(returns["optimal"] >= returns["random"] - 1e-9);
    CHECK(returns["optimal"] >= returns["random-split"] - 1e-9);
  }
}

}  // namespace

TEST_CASE("every policy partitions 200 generated shapes into rectangles exactly", "[env][properties]") {
  check_policies(200, 2022, false);
}

TEST_CASE("every policy partitions 60 generated shapes with holes into rectangles exactly", "[env][properties]") {
  check_policies(60, 2023, true);
}

TEST_CASE("random policies are reproducible from their seed", "[env][properties]") {
  const GridFace face = make_grid_face(test::generated_shapes(1, 9, {})[0].polygon);
  BaselineOptions options;
  options.seed = 42;
  auto a = make_baseline_policy("random", face.size, options);
  auto b = make_baseline_policy("random", face.size, options);
  CHECK(decompose_face(face, *a).total_return == decompose_face(face, *b).total_return);
}
