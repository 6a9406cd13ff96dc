// Replaying an episode to a step: pieces, the next cut, its line, and mismatched sequences.
#include <catch2/catch.hpp>

#include "core/baselines/baseline_policy.h"
#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/env/episode_snapshot.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

double pieces_area(const EpisodeSnapshot& s) {
  double area = 0;
  for (const SnapshotPiece& p : s.pieces) area += polygon_area(p.polygon);
  return area;
}

bool same_point(Point2 a, Point2 b) { return a.x == b.x && a.y == b.y; }

}  // namespace

TEST_CASE("snapshots of an L-shape follow its cut sequence", "[env][snapshot]") {
  const GridFace face = test::grid_face_of(test::l_shape());
  // The vertical cut at the re-entrant corner (1, 1) leaves two rectangles.
  const std::vector<CutSpec> cuts{{0, Point2{1, 1}, CutDirection::Vertical}};

  const EpisodeSnapshot start = episode_snapshot(face, cuts, 0);
  CHECK(start.step == 0);
  CHECK(start.steps == 1);
  REQUIRE(start.pieces.size() == 1);
  CHECK_FALSE(start.pieces[0].block);
  CHECK(start.pieces[0].polygon.outer.size() == 6);
  CHECK(start.blocks == 0);
  CHECK(start.return_so_far == 0.0);
  REQUIRE(start.has_next);
  CHECK(start.current_part_id == 0);
  CHECK(start.vertices.size() == 6);
  REQUIRE(start.chosen_vertex >= 0);
  CHECK(same_point(start.vertices[static_cast<size_t>(start.chosen_vertex)], Point2{1, 1}));
  CHECK(start.direction == CutDirection::Vertical);
  // The line x = 1 crosses the interior from y = 0 to y = 1 only (above, it runs along the boundary).
  REQUIRE(start.line.size() == 1);
  CHECK(same_point(start.line[0].a, Point2{1, 0}));
  CHECK(same_point(start.line[0].b, Point2{1, 1}));
  CHECK(start.n_parts == 2);
  CHECK(start.reward > 0);

  const EpisodeSnapshot end = episode_snapshot(face, cuts, 1);
  CHECK(end.step == 1);
  CHECK_FALSE(end.has_next);
  CHECK(end.status == EpisodeStatus::Complete);
  REQUIRE(end.pieces.size() == 2);
  CHECK(end.blocks == 2);
  for (const SnapshotPiece& p : end.pieces) {
    CHECK(p.block);
    CHECK(p.polygon.outer.size() == 4);
    CHECK(p.polygon.holes.empty());
  }
  CHECK(end.return_so_far == Approx(start.reward));
  CHECK(pieces_area(end) == Approx(3.0));
}

TEST_CASE("a cut along the boundary shows where the line touches the part", "[env][snapshot]") {
  const GridFace face = test::grid_face_of(test::l_shape());
  // The vertical line x = 2 through the convex corner (2, 0) only runs along the boundary: N = 1.
  const std::vector<CutSpec> cuts{{0, Point2{2, 0}, CutDirection::Vertical}, {0, Point2{1, 1}, CutDirection::Horizontal}};
  const EpisodeSnapshot first = episode_snapshot(face, cuts, 0);
  CHECK(first.n_parts == 1);
  CHECK(first.reward < 0);
  REQUIRE(first.line.size() == 1);
  CHECK(same_point(first.line[0].a, Point2{2, 0}));
  CHECK(same_point(first.line[0].b, Point2{2, 1}));
  // The part went to the back of the queue unchanged and is cut again.
  const EpisodeSnapshot second = episode_snapshot(face, cuts, 1);
  CHECK(second.current_part_id == 0);
  CHECK(second.pieces.size() == 1);
  CHECK(second.return_so_far == Approx(first.reward));
  CHECK(second.n_parts == 2);
}

TEST_CASE("a part with a hole becomes a polygon with a clockwise hole", "[env][snapshot]") {
  const GridFace face = test::grid_face_of(test::square3(), {test::centre_hole()});
  const RectilinearPolygon polygon = part_polygon(face.whole);
  CHECK(polygon.outer.size() == 4);
  REQUIRE(polygon.holes.size() == 1);
  CHECK(signed_area(polygon.outer) == Approx(9.0));
  CHECK(signed_area(polygon.holes[0]) == Approx(-1.0));
  CHECK(polygon_area(polygon) == Approx(8.0));
}

TEST_CASE("snapshots agree with the decomposition at every step", "[env][snapshot]") {
  for (bool holes : {false, true}) {
    GeneratorOptions options;
    options.holes = holes;
    const auto shapes = test::generated_shapes(15, holes ? 41 : 40, options);
    for (size_t s = 0; s < shapes.size(); ++s) {
      const GridFace face = make_grid_face(shapes[s].polygon);
      for (const std::string name : {"random", "optimal"}) {
        BaselineOptions baseline;
        baseline.seed = s;
        auto policy = make_baseline_policy(name, face.size, baseline);
        const Decomposition d = decompose_face(face, *policy);
        const std::vector<CutSpec> cuts = cut_specs(d.cuts);
        INFO("shape " << s << " holes " << holes << " policy " << name);
        double running = 0;
        int blocks = 0;
        for (int k = 0; k <= static_cast<int>(cuts.size()); ++k) {
          const EpisodeSnapshot snap = episode_snapshot(face, cuts, k);
          CHECK(pieces_area(snap) == Approx(face.whole.area()));
          CHECK(snap.return_so_far == Approx(running));
          CHECK(snap.blocks >= blocks);
          blocks = snap.blocks;
          if (k < static_cast<int>(cuts.size())) {
            const CutRecord& cut = d.cuts[static_cast<size_t>(k)];
            REQUIRE(snap.has_next);
            CHECK(snap.current_part_id == cut.part_id);
            CHECK(same_point(snap.vertices[static_cast<size_t>(snap.chosen_vertex)], cut.position));
            CHECK(snap.reward == Approx(cut.reward));
            CHECK(snap.n_parts == cut.n_parts);
            CHECK_FALSE(snap.line.empty());
            running += cut.reward;
          } else {
            CHECK_FALSE(snap.has_next);
            CHECK(snap.blocks == static_cast<int>(d.blocks.size()));
            CHECK(snap.return_so_far == Approx(d.total_return));
          }
        }
      }
    }
  }
}

TEST_CASE("a cut sequence that does not belong to the face is an input error", "[env][snapshot]") {
  const GridFace face = test::grid_face_of(test::l_shape());
  const std::vector<CutSpec> good{{0, Point2{1, 1}, CutDirection::Vertical}};
  CHECK_THROWS_AS(episode_snapshot(face, good, 2), InputError);
  CHECK_THROWS_AS(episode_snapshot(face, good, -1), InputError);
  const std::vector<CutSpec> wrong_part{{3, Point2{1, 1}, CutDirection::Vertical}};
  CHECK_THROWS_AS(episode_snapshot(face, wrong_part, 0), InputError);
  const std::vector<CutSpec> not_a_corner{{0, Point2{0.5, 1}, CutDirection::Vertical}};
  CHECK_THROWS_WITH(episode_snapshot(face, not_a_corner, 1), Catch::Contains("no corner of the part"));
  const std::vector<CutSpec> too_many{{0, Point2{1, 1}, CutDirection::Vertical}, {1, Point2{0, 0}, CutDirection::Vertical}};
  CHECK_THROWS_WITH(episode_snapshot(face, too_many, 2), Catch::Contains("already over"));
}

TEST_CASE("replaying a cut sequence gives the decomposition back", "[env][snapshot]") {
  GeneratorOptions options;
  options.holes = true;
  const auto shapes = test::generated_shapes(6, 44, options);
  for (size_t s = 0; s < shapes.size(); ++s) {
    const GridFace face = make_grid_face(shapes[s].polygon);
    auto policy = make_baseline_policy("greedy", face.size, BaselineOptions{});
    EpisodeOptions episode_options;
    episode_options.reward = RewardPreset::Mesh;
    const Decomposition d = decompose_face(face, *policy, episode_options);
    const std::vector<CutSpec> cuts = cut_specs(d.cuts);
    const Decomposition again = replay_decomposition(face, cuts, episode_options, "replay");
    INFO("shape " << s);
    CHECK(again.policy == "replay");
    CHECK(again.reward == RewardPreset::Mesh);
    CHECK(again.status == d.status);
    CHECK(again.total_return == Approx(d.total_return));
    REQUIRE(again.blocks.size() == d.blocks.size());
    for (size_t b = 0; b < d.blocks.size(); ++b) {
      CHECK(again.blocks[b].xmin == d.blocks[b].xmin);
      CHECK(again.blocks[b].ymax == d.blocks[b].ymax);
    }
    const Episode half = replay_episode(face, cuts, static_cast<int>(cuts.size() / 2), episode_options);
    CHECK(half.steps() == static_cast<int>(cuts.size() / 2));
    CHECK(half.running() == (cuts.size() / 2 < cuts.size()));
    // A sequence cut short is not the face's decomposition.
    if (!cuts.empty()) {
      const std::vector<CutSpec> short_cuts(cuts.begin(), cuts.end() - 1);
      CHECK_THROWS_WITH(replay_decomposition(face, short_cuts, episode_options, "replay"),
                        Catch::Contains("ends after"));
    }
  }
}
