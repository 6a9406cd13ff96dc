// NodeBuckets: records written in place by their node's bucket and each bucket sorted come out as
// std::sort by (node, full order) leaves them, on random records and on edge cases (empty buckets, a
// node with every record, no record).
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "core/mesh/node_buckets.h"

using namespace autoblock;

namespace {

// Records (node, value) bucketed by node and sorted, against std::sort of the pairs.
void check_sorted_like_std(const std::vector<std::pair<int, int>>& records, size_t nodes) {
  NodeBuckets buckets(nodes);
  for (const auto& r : records) buckets.count(static_cast<size_t>(r.first));
  std::vector<std::pair<int, int>> placed(buckets.close());
  REQUIRE(placed.size() == records.size());
  for (const auto& r : records) placed[buckets.place(static_cast<size_t>(r.first))] = r;
  buckets.sort(placed, [](const auto& a, const auto& b) { return a < b; });
  std::vector<std::pair<int, int>> expected = records;
  std::sort(expected.begin(), expected.end());
  CHECK(placed == expected);
}

}  // namespace

TEST_CASE("node buckets sort records as std::sort by node first", "[mesh][hex]") {
  std::mt19937 rng(7);
  for (size_t nodes : {1u, 5u, 100u}) {
    std::uniform_int_distribution<int> node(0, static_cast<int>(nodes) - 1), value(-50, 50);
    std::vector<std::pair<int, int>> records;
    for (int k = 0; k < 500; ++k) records.push_back({node(rng), value(rng)});
    check_sorted_like_std(records, nodes);
  }
  check_sorted_like_std({}, 4);                              // no record
  check_sorted_like_std({{3, 2}, {3, -1}, {3, 2}, {3, 0}}, 10);  // one bucket, repeats, the others empty
}
