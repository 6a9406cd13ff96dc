// Interval assignment on a general block model (GLPK): equal opposite totals, fixed counts, errors.
#include "core/mesh/edge_intervals.h"

#include <algorithm>

#include <catch2/catch.hpp>

#include "core/common/error.h"

using namespace autoblock;
using Catch::Matchers::Contains;

namespace {

constexpr double kQ = 1e-7;

RegionDecomposition one_block(const Ring& ring) {
  RegionDecomposition d;
  d.status = EpisodeStatus::Complete;
  FinishedRegion f;
  f.region = Region(ring, {}, kQ);
  const auto corners = block_corners(f.region);
  REQUIRE(corners);
  f.corners = *corners;
  d.finished.push_back(f);
  return d;
}

}  // namespace

TEST_CASE("edge intervals: a rectangle gets counts near length / h", "[mesh][intervals][general]") {
  const BlockModel m = block_model(one_block(Ring{{0, 0}, {4, 0}, {4, 1}, {0, 1}}), BlockRules{}, kQ);
  IntervalOptions options;
  options.target_size = 0.5;
  const IntervalAssignment a = assign_edge_intervals(m, options);
  REQUIRE(a.intervals.size() == 4);
  for (size_t e = 0; e < 4; ++e) CHECK(a.intervals[e] == static_cast<int>(std::lround(m.edges[e].length / 0.5)));
  CHECK(a.max_relative_deviation == Approx(0.0).margin(1e-12));
  CHECK(a.quads == 16);
  CHECK(quad_count(m, a.intervals) == 16);
}

TEST_CASE("edge intervals: a trapezoid's short side takes its long side's count", "[mesh][intervals][general]") {
  // Bottom 6, top 2: opposite sides must carry equal counts whatever their lengths.
  const BlockModel m = block_model(one_block(Ring{{0, 0}, {6, 0}, {4, 2}, {2, 2}}), BlockRules{}, kQ);
  IntervalOptions options;
  options.target_size = 1.0;
  const IntervalAssignment a = assign_edge_intervals(m, options);
  const ModelBlock& b = m.blocks[0];
  CHECK(side_intervals(b.sides[0], a.intervals) == side_intervals(b.sides[2], a.intervals));
  CHECK(side_intervals(b.sides[1], a.intervals) == side_intervals(b.sides[3], a.intervals));
  // 6 and 2 against h = 1: the best compromise on the largest factor max(g / n, n / g) is n = 3 or 4.
  const int n = side_intervals(b.sides[0], a.intervals);
  CHECK((n == 3 || n == 4));
}

TEST_CASE("edge intervals: a target count per edge is aimed at, and traded against the opposite side", "[mesh][intervals][general]") {
  // Bottom 6, top 2 at h = 1 (3 or 4 without a target, as above). The top edge is given a target count:
  // 6 agrees with the bottom, so both get 6; 12 disagrees, and the largest factor max(g / n, n / g) is
  // smallest near sqrt(6 * 12), between the two (a target is not a minimum).
  const BlockModel m = block_model(one_block(Ring{{0, 0}, {6, 0}, {4, 2}, {2, 2}}), BlockRules{}, kQ);
  size_t top = m.edges.size();
  for (size_t e = 0; e < m.edges.size(); ++e) {
    if (m.vertices[static_cast<size_t>(m.edges[e].a)].y == 2 && m.vertices[static_cast<size_t>(m.edges[e].b)].y == 2) top = e;
  }
  REQUIRE(top < m.edges.size());
  IntervalOptions options;
  options.target_size = 1.0;
  options.edge_target.assign(m.edges.size(), 0.0);
  options.edge_target[top] = 6.0;
  CHECK(assign_edge_intervals(m, options).intervals[top] == 6);
  options.edge_target[top] = 12.0;
  const int n = assign_edge_intervals(m, options).intervals[top];
  CHECK(n >= 8);
  CHECK(n <= 9);
  options.edge_target[top] = 1.0;  // below the length over h: no effect
  const int plain = assign_edge_intervals(m, options).intervals[top];
  CHECK((plain == 3 || plain == 4));
}

TEST_CASE("edge intervals: a minimum count per edge holds where the size would give fewer", "[mesh][intervals][general]") {
  // A 4 x 1 rectangle at h = 2: the short sides would get one interval each.
  const BlockModel m = block_model(one_block(Ring{{0, 0}, {4, 0}, {4, 1}, {0, 1}}), BlockRules{}, kQ);
  IntervalOptions options;
  options.target_size = 2.0;
  const IntervalAssignment coarse = assign_edge_intervals(m, options);
  CHECK(*std::min_element(coarse.intervals.begin(), coarse.intervals.end()) == 1);
  options.min_intervals = 2;
  const IntervalAssignment fine = assign_edge_intervals(m, options);
  CHECK(*std::min_element(fine.intervals.begin(), fine.intervals.end()) == 2);
  CHECK(fine.quads == 4);  // 2 x 2: the long sides keep their 2
}

TEST_CASE("edge intervals: fixed counts hold or are refused with a reason", "[mesh][intervals][general]") {
  const BlockModel m = block_model(one_block(Ring{{0, 0}, {4, 0}, {4, 1}, {0, 1}}), BlockRules{}, kQ);
  IntervalOptions options;
  options.target_size = 0.5;
  options.fixed.push_back(fixed_edge_intervals(m, {0, 0}, {4, 0}, 3, 1e-9));
  const IntervalAssignment a = assign_edge_intervals(m, options);
  const ModelBlock& b = m.blocks[0];
  CHECK(side_intervals(b.sides[0], a.intervals) == 3);
  CHECK(side_intervals(b.sides[2], a.intervals) == 3);  // the opposite side follows
  // Opposite sides fixed differently cannot hold.
  options.fixed.push_back(fixed_edge_intervals(m, {4, 1}, {0, 1}, 5, 1e-9));
  CHECK_THROWS_WITH(assign_edge_intervals(m, options), Contains("cannot all hold"));
  // A stretch that does not end at model vertices, or is not on the model's edges.
  CHECK_THROWS_WITH(fixed_edge_intervals(m, {0, 0}, {3, 0}, 2, 1e-9), Contains("block corners or T-junctions"));
  CHECK_THROWS_WITH(fixed_edge_intervals(m, {0, 0}, {4, 1}, 2, 1e-9), Contains("not a straight stretch"));
  options.fixed.clear();
  options.target_size = -1.0;
  CHECK_THROWS_AS(assign_edge_intervals(m, options), InputError);
  options.target_size = 1e-6;
  CHECK_THROWS_WITH(assign_edge_intervals(m, options), Contains("quadrilaterals (limit"));
}

TEST_CASE("edge intervals: GLPK's work is counted, the same for the same program", "[mesh][intervals][general]") {
  // The counts are decided by simplex iterations, not seconds (kIntervalQuickIterations): the same
  // program gets the same counts and the same work, which mesh_input_face's tries add up.
  const BlockModel m = block_model(one_block(Ring{{0, 0}, {6, 0}, {4, 2}, {2, 2}}), BlockRules{}, kQ);
  std::vector<long long> work(3, 0);
  std::vector<std::vector<int>> counts;
  for (long long& w : work) {
    IntervalOptions options;
    options.target_size = 0.37;
    options.simplex_work = &w;
    counts.push_back(assign_edge_intervals(m, options).intervals);
  }
  CHECK(work[0] > 0);
  CHECK(work[1] == work[0]);
  CHECK(work[2] == work[0]);
  CHECK(counts[1] == counts[0]);
  CHECK(counts[2] == counts[0]);
  // Added to, not set.
  long long total = 5;
  IntervalOptions options;
  options.target_size = 0.37;
  options.simplex_work = &total;
  assign_edge_intervals(m, options);
  CHECK(total == 5 + work[0]);
}
