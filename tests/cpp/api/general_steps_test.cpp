// Stepping through and replaying a general face's action sequence through core/api
// (face_step_general, face_replay_general; region/region_snapshot.h underneath): what the workbench's
// step-through panel and a reopened document use.
#include "support/catch_torch.h"

#include <vector>

#include "core/api/face_actions.h"
#include "core/common/error.h"
#include "core/data/general_generator.h"
#include "core/geometry/occt_face.h"
#include "core/geometry/occt_properties.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

InputFace generated_face(std::uint64_t seed, GeneralKind kind, bool holes) {
  return check_face(occt_face_from_polygon(test::general_polygon(seed, kind, holes), 2.0, true), "generated");
}

RegionDecomposition decomposed(const InputFace& face, const std::string& policy) {
  DecomposeSettings settings;
  settings.policy = policy;
  settings.occt_blocks = false;
  settings.policy_settings.general_time_limit = 0.5;
  return decompose_input_face(face, settings).region;
}

double area_of(const std::vector<RegionSnapshotPiece>& pieces) {
  double area = 0.0;
  for (const RegionSnapshotPiece& p : pieces) area += p.region.area();
  return area;
}

}  // namespace

TEST_CASE("a general sequence replays to the same decomposition, and every step shows its part of it",
          "[api][general][steps]") {
  int sequences = 0;
  for (const GeneralKind kind : {GeneralKind::Polygon, GeneralKind::Chamfered}) {
    for (const bool holes : {false, true}) {
      for (const char* policy : {"greedy", "search", "random"}) {
        const InputFace face = generated_face(holes ? 31 : 17, kind, holes);
        REQUIRE(face.is_general());
        const RegionDecomposition d = decomposed(face, policy);
        REQUIRE(d.complete());
        INFO(general_kind_name(kind) << " holes " << holes << " " << policy << ", " << d.cuts.size() << " actions");
        const std::vector<RegionActionSpec> actions = region_action_specs(d.cuts);

        const RegionDecomposition again = face_replay_general(face, actions, 0, d.reward, "replay", false).region;
        CHECK(again.complete());
        CHECK(again.total_return == Approx(d.total_return).margin(1e-12));
        CHECK(again.blocks == d.blocks);
        CHECK(again.templates == d.templates);
        REQUIRE(again.finished.size() == d.finished.size());
        for (size_t i = 0; i < d.finished.size(); ++i) CHECK(again.finished[i].region == d.finished[i].region);

        double before = 0.0;
        for (int k = 0; k <= static_cast<int>(actions.size()); ++k) {
          const RegionSnapshot s = face_step_general(face, actions, k, 0, d.reward);
          CHECK(s.step == k);
          CHECK(s.steps == static_cast<int>(actions.size()));
          CHECK(s.return_so_far == Approx(before).margin(1e-9));
          // The pieces always tile the face.
          CHECK(area_of(s.pieces) == Approx(face.region.area()).epsilon(1e-6));  // pieces are rounded to the lattice
          if (k == static_cast<int>(actions.size())) {
            CHECK_FALSE(s.has_next);
            CHECK(s.status == EpisodeStatus::Complete);
            CHECK(s.blocks == d.blocks);
            for (const RegionSnapshotPiece& p : s.pieces) CHECK(p.finished);
            break;
          }
          const RegionCutRecord& record = d.cuts[static_cast<size_t>(k)];
          REQUIRE(s.has_next);
          CHECK(s.current_part_id == record.part_id);
          CHECK(s.reward == Approx(record.reward).margin(1e-12));
          CHECK(s.n_parts == record.n_parts);
          CHECK(s.chords.size() == record.chords.size());
          if (record.action.kind == RegionAction::Kind::Cut) {
            // The origin lies on the part's boundary: at a listed vertex, or on an edge (-1).
            if (s.chosen_vertex >= 0) {
              const Point2 v = s.vertices[static_cast<size_t>(s.chosen_vertex)];
              CHECK(std::hypot(v.x - record.action.cut.origin.x, v.y - record.action.cut.origin.y) <=
                    face.region.quantum());
            }
            if (record.n_parts > 1) CHECK_FALSE(s.chords.empty());
          } else {
            CHECK(s.chosen_vertex == -1);
            CHECK(s.chords.empty());
          }
          before += record.reward;
        }
        ++sequences;
      }
    }
  }
  CHECK(sequences == 12);
}

TEST_CASE("a replayed general sequence gives its blocks as faces, without searching again", "[api][general][steps]") {
  const InputFace face = generated_face(31, GeneralKind::Polygon, true);
  DecomposeSettings settings;
  settings.policy = "search";
  const FaceDecomposition searched = decompose_input_face(face, settings);
  const FaceDecomposition replayed =
      face_replay_general(face, region_action_specs(searched.region.cuts), 0, searched.region.reward, "search");
  CHECK(replayed.region.policy == "search");
  CHECK(replayed.region.total_return == Approx(searched.region.total_return).margin(1e-12));
  REQUIRE(replayed.block_faces.size() == searched.block_faces.size());
  for (size_t i = 0; i < replayed.block_faces.size(); ++i) {
    CHECK(occt_area(replayed.block_faces[i]) == Approx(occt_area(searched.block_faces[i])).epsilon(1e-9));
  }
  CHECK(occt_area(replayed.shape) == Approx(occt_area(face.model)).epsilon(1e-6));
  CHECK(occt_shape_valid(replayed.shape));
}

TEST_CASE("a general sequence that does not belong to the face is an input error", "[api][general][steps][errors]") {
  const InputFace face = generated_face(17, GeneralKind::Chamfered, true);
  const RegionDecomposition d = decomposed(face, "greedy");
  REQUIRE(d.cuts.size() >= 2);
  const std::vector<RegionActionSpec> actions = region_action_specs(d.cuts);

  CHECK_THROWS_WITH(face_step_general(face, actions, static_cast<int>(actions.size()) + 1),
                    Catch::Contains("out of range"));
  CHECK_THROWS_AS(face_step_general(face, actions, -1), InputError);

  std::vector<RegionActionSpec> wrong_part = actions;
  wrong_part[0].part_id = 7;
  CHECK_THROWS_WITH(face_step_general(face, wrong_part, 1), Catch::Contains("does not belong to this face"));
  CHECK_THROWS_WITH(face_step_general(face, wrong_part, 0), Catch::Contains("action 1 cuts part 7"));

  std::vector<RegionActionSpec> far_away = actions;
  far_away[0].action = region_action_of_kind("full");
  far_away[0].action.cut.origin = {1e6, 1e6};
  CHECK_THROWS_WITH(face_replay_general(face, far_away, 0, d.reward), Catch::Contains("away from the boundary"));

  std::vector<RegionActionSpec> no_direction = actions;
  no_direction[0].action = region_action_of_kind("partial");
  no_direction[0].action.cut.origin = face.region.outer()[0];
  no_direction[0].action.cut.direction = {0.0, 0.0};
  CHECK_THROWS_WITH(face_step_general(face, no_direction, 1), Catch::Contains("non-zero direction"));

  // The face has a hole, so it is not convex: no template.
  std::vector<RegionActionSpec> template_first = actions;
  template_first[0].action = region_action_of_kind("template");
  CHECK_THROWS_WITH(face_step_general(face, template_first, 1), Catch::Contains("needs a convex part"));
  CHECK_THROWS_WITH(region_action_of_kind("diagonal"), Catch::Contains("unknown action kind 'diagonal'"));

  // Cut short: parts are left.
  const std::vector<RegionActionSpec> short_sequence(actions.begin(), actions.end() - 1);
  CHECK_THROWS_WITH(face_replay_general(face, short_sequence, 0, d.reward), Catch::Contains("left to cut"));
  // One action too many: the face is finished before it.
  std::vector<RegionActionSpec> long_sequence = actions;
  long_sequence.push_back(actions.back());
  CHECK_THROWS_WITH(face_replay_general(face, long_sequence, 0, d.reward), Catch::Contains("every part is finished"));

  // A rectilinear face's sequence is by vertex and axis.
  const InputFace grid = check_face(occt_face_from_polygon(test::polygon_of(test::l_shape()), 0.0, true), "L");
  REQUIRE_FALSE(grid.is_general());
  CHECK_THROWS_WITH(face_step_general(grid, {}, 0), Catch::Contains("two perpendicular directions"));
}
