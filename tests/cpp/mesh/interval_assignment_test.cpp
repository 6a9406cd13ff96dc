// Interval assignment: strips, the GLPK program, naive rounding's failure, infeasible requests.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/baselines/baseline_policy.h"
#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/mesh/interval_assignment.h"
#include "core/mesh/strip_layout.h"
#include "support/mesh_fixtures.h"
#include "support/test_shapes.h"

using namespace autoblock;
using Catch::Matchers::Contains;

namespace {

double best_deviation(double length, double h) {
  double best = 1e300;
  for (int k = 1; k <= static_cast<int>(std::ceil(length / h)) + 2; ++k) best = std::min(best, std::fabs(length / k - h) / h);
  return best;
}

// Total intervals along a stretch of a horizontal (column strips) or vertical line.
int total_along(const StripLayout& layout, const IntervalAssignment& a, StripAxis axis, int line, int from, int to) {
  int total = 0;
  for (int s : strips_along(layout, axis, line, from, to)) total += a.intervals[static_cast<size_t>(s)];
  return total;
}

}  // namespace

TEST_CASE("a T-junction line crosses the neighbour: strips of a two-over-one model", "[mesh][intervals]") {
  // [0,3] x [0,2]: one block below, two above meeting at x = 1.5 (a T-junction on the lower block).
  const test::HandModel m =
      test::hand_model({{0, 0}, {3, 0}, {3, 2}, {0, 2}}, {}, {Box{0, 0, 3, 1}, Box{0, 1, 1.5, 2}, Box{1.5, 1, 3, 2}});
  int columns = 0, rows = 0;
  for (const Strip& s : m.layout.strips) (s.axis == StripAxis::Column ? columns : rows)++;
  CHECK(columns == 2);  // x = 1.5 runs down through the lower block
  CHECK(rows == 2);
  CHECK(m.layout.cells.size() == 4);
}

TEST_CASE("naive rounding fails where the integer program does not", "[mesh][intervals]") {
  // Lower block [0,3] x [0,1]; above it [0,1.5] and [1.5,3]. Target h = 1.
  const test::HandModel m =
      test::hand_model({{0, 0}, {3, 0}, {3, 2}, {0, 2}}, {}, {Box{0, 0, 3, 1}, Box{0, 1, 1.5, 2}, Box{1.5, 1, 3, 2}});
  const double h = 1.0;
  // Naive: round every edge of the block model on its own. The lower block's bottom edge (length
  // 3) gets 3; its top side is two edges of 1.5 (imprinted T-junction), each rounded to 2.
  const int bottom = static_cast<int>(std::lround(3.0 / h));
  const int top = 2 * static_cast<int>(std::lround(1.5 / h));
  REQUIRE(bottom != top);  // opposite sides differ: no mapped mesh
  IntervalOptions options;
  options.target_size = h;
  const IntervalAssignment a = assign_intervals(m.layout, options);
  REQUIRE(m.layout.grid->xs.size() == 3);  // 0, 1.5, 3
  // Both sides of the lower block and both of every upper block have equal totals.
  CHECK(total_along(m.layout, a, StripAxis::Column, 0, 0, 2) == total_along(m.layout, a, StripAxis::Column, 1, 0, 2));
  CHECK(total_along(m.layout, a, StripAxis::Column, 1, 0, 1) == total_along(m.layout, a, StripAxis::Column, 2, 0, 1));
  CHECK(total_along(m.layout, a, StripAxis::Row, 0, 0, 1) == total_along(m.layout, a, StripAxis::Row, 2, 0, 1));
  // Size-optimal, not count-rounding: 1.5 / 2 = 0.75 deviates 25 %, 1.5 / 1 = 1.5 deviates 50 %.
  for (const Strip& s : m.layout.strips) {
    if (s.axis == StripAxis::Column) CHECK(a.intervals[static_cast<size_t>(&s - m.layout.strips.data())] == 2);
  }
  CHECK(a.max_relative_deviation == Approx(0.25));
  CHECK(a.max_deviation == Approx(0.25));
  CHECK(a.optimal);
  CHECK(a.quads == quad_count(m.layout, a.intervals));
  CHECK(a.quads == 8);
}

TEST_CASE("fixed counts couple strips, and rounding each strip breaks them", "[mesh][intervals]") {
  const test::HandModel m =
      test::hand_model({{0, 0}, {3, 0}, {3, 2}, {0, 2}}, {}, {Box{0, 0, 3, 1}, Box{0, 1, 1.5, 2}, Box{1.5, 1, 3, 2}});
  IntervalOptions options;
  options.target_size = 1.0;
  options.fixed.push_back(fixed_intervals_on(m.layout, {0, 0}, {3, 0}, 3, 1e-9));
  REQUIRE(options.fixed[0].strips.size() == 2);
  // Each strip alone would take 2 (see above): 4 != 3.
  const IntervalAssignment a = assign_intervals(m.layout, options);
  const int n0 = a.intervals[static_cast<size_t>(options.fixed[0].strips[0])];
  const int n1 = a.intervals[static_cast<size_t>(options.fixed[0].strips[1])];
  CHECK(n0 + n1 == 3);
  CHECK(std::min(n0, n1) == 1);
  CHECK(a.max_relative_deviation == Approx(0.5));  // 1.5 / 1: the best any split of 3 can do
  // The top of the lower block follows: it is the same strips.
  CHECK(total_along(m.layout, a, StripAxis::Column, 1, 0, 2) == 3);
}

TEST_CASE("interval assignment matches the per-strip optimum on generated faces", "[mesh][intervals]") {
  for (bool holes : {false, true}) {
    GeneratorOptions options;
    options.holes = holes;
    const auto shapes = test::generated_shapes(40, holes ? 81 : 80, options);
    for (size_t s = 0; s < shapes.size(); ++s) {
      const GridFace face = make_grid_face(shapes[s].polygon);
      auto policy = make_baseline_policy("optimal", face.size, BaselineOptions{});
      const Decomposition d = decompose_face(face, *policy);
      const StripLayout layout = strip_layout(face, d.blocks);
      for (double fraction : {0.05, 0.13}) {
        IntervalOptions io;
        io.target_size = fraction * face.size;
        const IntervalAssignment a = assign_intervals(layout, io);
        INFO("shape " << s << " holes " << holes << " h " << io.target_size);
        double worst = 0;
        for (size_t k = 0; k < layout.strips.size(); ++k) {
          const double len = layout.strips[k].length();
          REQUIRE(a.intervals[k] >= 1);
          // Without fixed counts the strips are independent: each must be at its own optimum.
          CHECK(std::fabs(len / a.intervals[k] - io.target_size) / io.target_size ==
                Approx(best_deviation(len, io.target_size)).margin(1e-12));
          worst = std::max(worst, best_deviation(len, io.target_size));
        }
        CHECK(a.max_relative_deviation == Approx(worst).margin(1e-12));
        // Every block: opposite sides get equal totals.
        const Grid& g = *face.grid;
        for (const Box& b : d.blocks) {
          const auto at = [](const std::vector<double>& v, double x) {
            return static_cast<int>(std::lower_bound(v.begin(), v.end(), x) - v.begin());
          };
          const int i0 = at(g.xs, b.xmin), i1 = at(g.xs, b.xmax), j0 = at(g.ys, b.ymin), j1 = at(g.ys, b.ymax);
          CHECK(total_along(layout, a, StripAxis::Column, j0, i0, i1) == total_along(layout, a, StripAxis::Column, j1, i0, i1));
          CHECK(total_along(layout, a, StripAxis::Row, i0, j0, j1) == total_along(layout, a, StripAxis::Row, i1, j0, j1));
        }
      }
    }
  }
}

TEST_CASE("infeasible interval requests get clear errors", "[mesh][intervals][errors]") {
  const test::HandModel m =
      test::hand_model({{0, 0}, {3, 0}, {3, 2}, {0, 2}}, {}, {Box{0, 0, 3, 1}, Box{0, 1, 1.5, 2}, Box{1.5, 1, 3, 2}});
  IntervalOptions options;
  options.target_size = 1.0;
  SECTION("fewer intervals than strips") {
    options.fixed.push_back(fixed_intervals_on(m.layout, {0, 0}, {3, 0}, 1, 1e-9));
    CHECK_THROWS_WITH(assign_intervals(m.layout, options), Contains("edge (0, 0)-(3, 0) cannot have 1 interval") &&
                                                               Contains("2 strips"));
  }
  SECTION("opposite sides fixed to different counts") {
    options.fixed.push_back(fixed_intervals_on(m.layout, {0, 0}, {0, 1}, 3, 1e-9));
    options.fixed.push_back(fixed_intervals_on(m.layout, {3, 0}, {3, 1}, 4, 1e-9));
    CHECK_THROWS_AS(assign_intervals(m.layout, options), InputError);
    CHECK_THROWS_WITH(assign_intervals(m.layout, options), Contains("cannot all hold"));
  }
  SECTION("a stretch ending inside a strip or off the face") {
    CHECK_THROWS_WITH(fixed_intervals_on(m.layout, {0, 0}, {1, 0}, 2, 1e-9), Contains("not a corner coordinate"));
    CHECK_THROWS_WITH(fixed_intervals_on(m.layout, {0, 0}, {3, 1}, 2, 1e-9), Contains("not a stretch parallel"));
    // A U whose right arm is taller: y = 2 is a grid line but no mesh line crosses the right arm.
    const test::HandModel u = test::hand_model({{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {},
                                               {Box{0, 0, 3, 1}, Box{0, 1, 1, 2}, Box{2, 1, 3, 3}});
    CHECK_THROWS_WITH(fixed_intervals_on(u.layout, {3, 0}, {3, 2}, 4, 1e-9), Contains("ends inside a mesh strip"));
    CHECK_NOTHROW(fixed_intervals_on(u.layout, {3, 0}, {3, 3}, 4, 1e-9));
    CHECK_THROWS_WITH(fixed_intervals_on(u.layout, {1, 2}, {2, 2}, 4, 1e-9), Contains("not on the face"));
  }
  SECTION("bad or huge sizes") {
    for (double h : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
      options.target_size = h;
      CHECK_THROWS_AS(assign_intervals(m.layout, options), InputError);
    }
    options.target_size = 1e-6;
    CHECK_THROWS_WITH(assign_intervals(m.layout, options), Contains("quadrilaterals (limit"));
  }
}
