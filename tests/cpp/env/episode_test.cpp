#include <catch2/catch.hpp>

#include "core/env/episode.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {
int vertex_at(const Episode& e, int i, int j) {
  const auto& v = e.current_vertices();
  for (int k = 0; k < static_cast<int>(v.size()); ++k) {
    if (v[static_cast<size_t>(k)].corner.i == i && v[static_cast<size_t>(k)].corner.j == j) return k;
  }
  FAIL("no vertex at (" << i << ", " << j << ")");
  return -1;
}
}  // namespace

TEST_CASE("a rectangle is complete before any cut", "[env][episode]") {
  Episode e(test::grid_face_of({{0, 0}, {5, 0}, {5, 1}, {0, 1}}));
  CHECK(e.status() == EpisodeStatus::Complete);
  CHECK(e.blocks().size() == 1);
  CHECK(e.steps() == 0);
  CHECK(e.total_return() == 0);
}

TEST_CASE("one cut at the L-shape's re-entrant corner completes the episode", "[env][episode]") {
  Episode e(test::grid_face_of(test::l_shape()));
  REQUIRE(e.running());
  CHECK(e.current_vertices().size() == 6);
  const CutRecord& cut = e.step(Action{vertex_at(e, 1, 1), CutDirection::Vertical});
  CHECK(cut.part_id == 0);
  CHECK(cut.n_parts == 2);
  CHECK(cut.children == std::vector<int>{1, 2});
  CHECK(cut.reward == Approx(10.2849941604));
  CHECK(e.status() == EpisodeStatus::Complete);
  CHECK(e.blocks().size() == 2);
  CHECK(e.total_return() == Approx(10.2849941604));
}

TEST_CASE("a cut that changes nothing costs -3 and keeps the part", "[env][episode]") {
  Episode e(test::grid_face_of(test::l_shape()));
  const CutRecord& cut = e.step(Action{vertex_at(e, 0, 0), CutDirection::Horizontal});
  CHECK(cut.n_parts == 1);
  CHECK(cut.children == std::vector<int>{0});
  CHECK(cut.reward == Approx(-3.0));
  CHECK(e.running());
  CHECK(e.current_part_id() == 0);
}

TEST_CASE("pieces are queued first in, first out", "[env][episode]") {
  // A bar 0..5 x 1..2 with posts down at 0..1 and 4..5 and a post up at 2..3:
  //          +--+
  //   +------+  +-----+
  //   |               |
  //   +--+         +--+
  //      +---------+ (posts reach y = 0)
  // The vertical cut through (2,2) leaves two non-rectangular pieces: the left L (lowest-left
  // cell, so queued first) and the right part.
  Episode e(test::grid_face_of({{0, 0}, {1, 0}, {1, 1}, {4, 1}, {4, 0}, {5, 0}, {5, 2}, {3, 2}, {3, 3}, {2, 3}, {2, 2}, {0, 2}}));
  const CutRecord& first = e.step(Action{vertex_at(e, 2, 2), CutDirection::Vertical});
  REQUIRE(first.n_parts == 2);
  REQUIRE(e.queue().size() == 2);
  CHECK(e.current_part_id() == first.children[0]);
  const int right = first.children[1];
  const CutRecord& second = e.step(Action{vertex_at(e, 1, 1), CutDirection::Vertical});
  CHECK(second.n_parts == 2);
  CHECK(e.current_part_id() == right);
  CHECK(e.blocks().size() == 2);
}

TEST_CASE("the step cap ends an episode as truncated", "[env][episode]") {
  EpisodeOptions options;
  options.max_steps = 3;
  Episode e(test::grid_face_of(test::l_shape()), options);
  for (int k = 0; k < 3; ++k) e.step(Action{vertex_at(e, 0, 0), CutDirection::Horizontal});
  CHECK(e.status() == EpisodeStatus::Truncated);
  CHECK(e.queue().size() == 1);
  CHECK(e.total_return() == Approx(-9.0));
  CHECK_THROWS_AS(e.step(Action{0, CutDirection::Horizontal}), std::logic_error);
}

TEST_CASE("two parts in the queue are cut in the order they were made", "[env][episode]") {
  // A plus sign's horizontal cut through its lower re-entrant corners leaves the bottom stem
  // (rectangle) and a T (queued); the T's cut leaves rectangles.
  Episode e(test::grid_face_of({{1, 0}, {2, 0}, {2, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 3}, {1, 3}, {1, 2}, {0, 2}, {0, 1}, {1, 1}}));
  const CutRecord& first = e.step(Action{vertex_at(e, 1, 1), CutDirection::Vertical});
  // x = 1 splits off the left arm (rectangle) and leaves a T.
  REQUIRE(first.n_parts == 2);
  const int t_id = e.current_part_id();
  const CutRecord& second = e.step(Action{vertex_at(e, 2, 1), CutDirection::Vertical});
  CHECK(second.part_id == t_id);
  CHECK(e.status() == EpisodeStatus::Complete);
  CHECK(e.blocks().size() == 3);
}
