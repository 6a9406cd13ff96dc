#include "core/sac/region_lookahead.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/data/arc_generator.h"
#include "core/geometry/tolerance.h"
#include "core/io/input_face.h"
#include "core/region/block.h"
#include "core/region/region_cut.h"
#include "core/region/region_reward.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("region lookahead of an L: the re-entrant corner's two best cuts each leave two blocks", "[sac][region]") {
  // The L (0,0) (2,0) (2,1) (1,1) (1,2) (0,2): the extensions of the edges at (1,1) cut it into a 2 x 1
  // and a 1 x 1 block or a 1 x 2 and a 1 x 1, the same reward by symmetry (about the diagonal).
  const auto lock = lock_general_engine();
  const Region l(Ring{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}, 1e-7);
  for (const RewardPreset preset : {RewardPreset::Paper, RewardPreset::Mesh}) {
    RegionEpisodeOptions options;
    options.reward = preset;
    const RegionLookahead look = region_look_ahead(l, 2.0, options);
    REQUIRE(look.vertex_features.size() == 6);
    int reflex_vertex = -1;
    for (size_t v = 0; v < 6; ++v) {
      if (look.vertex_features[v][0] == 1.0f) {
        CHECK(reflex_vertex == -1);
        reflex_vertex = static_cast<int>(v);
      }
    }
    REQUIRE(reflex_vertex >= 0);
    const Ring flat = l.outer();
    CHECK(flat[static_cast<size_t>(reflex_vertex)] == Point2{1, 1});
    const auto& f = look.vertex_features[static_cast<size_t>(reflex_vertex)];
    CHECK(f[1] == Approx(f[2]));
    CHECK(f[3] == 0.5f);  // N = 2
    CHECK(f[4] == 0.5f);
    CHECK(f[5] == 1.0f);  // both pieces blocks
    CHECK(f[6] == 1.0f);
    CHECK(look.scale[0] == Approx(1.0));
    CHECK(look.scale[1] == Approx(std::sqrt(3.0) / 2.0));
  }
}

TEST_CASE("region lookahead on general faces: candidates as the engine scores them, summaries their best two",
          "[sac][region]") {
  const auto lock = lock_general_engine();
  int with_vertex = 0, candidates = 0;
  for (int i = 0; i < 10; ++i) {
    const Region face =
        test::region_of(test::general_polygon(700 + i, i % 2 ? GeneralKind::Chamfered : GeneralKind::Polygon, i % 3 == 0));
    RegionEpisodeOptions options;
    options.reward = i % 2 ? RewardPreset::Paper : RewardPreset::Mesh;
    const double face_size = face.bbox().longer_side();
    for (const Region& part : test::face_and_first_pieces(face, 3)) {
      if (is_block(part, options.rules)) continue;
      const RegionLookahead look = region_look_ahead(part, face_size, options);
      REQUIRE(look.vertex_features.size() == static_cast<size_t>(part.vertex_count()));
      const std::vector<Ring> loops = part.loops();
      std::vector<Point2> vertices;
      for (const Ring& loop : loops) vertices.insert(vertices.end(), loop.begin(), loop.end());
      std::vector<double> best(vertices.size(), -1e300), second(vertices.size(), -1e300);
      const double scale = lookahead_reward_scale(options.reward);
      for (const RegionCandidate& c : look.candidates) {
        ++candidates;
        if (c.action.kind == RegionAction::Kind::Template) {
          CHECK(c.vertex == -1);
          continue;
        }
        // The reward and the pieces of the cut made again.
        const CutOutcome outcome = cut_region(part, c.action.cut);
        CHECK(c.reward == Approx(region_cut_reward(options.reward, outcome, face_size, options.rules)));
        CHECK(c.pieces == static_cast<int>(outcome.pieces.size()));
        CHECK(c.blocks + static_cast<int>(c.to_cut.size()) == c.pieces);
        if (c.vertex < 0) continue;
        ++with_vertex;
        REQUIRE(c.vertex < static_cast<int>(vertices.size()));
        CHECK(c.action.cut.origin == vertices[static_cast<size_t>(c.vertex)]);
        double& b = best[static_cast<size_t>(c.vertex)];
        double& s = second[static_cast<size_t>(c.vertex)];
        if (c.reward > b) {
          s = b;
          b = c.reward;
        } else if (c.reward > s) {
          s = c.reward;
        }
      }
      for (size_t v = 0; v < vertices.size(); ++v) {
        const auto& f = look.vertex_features[v];
        for (const float x : f) CHECK(std::isfinite(x));
        // A missing cut reads as one that separates nothing (N = 1, no block).
        const double nothing = region_cut_reward(options.reward, CutOutcome{{part}, {}}, face_size, options.rules) / scale;
        CHECK(f[1] == Approx(best[v] > -1e300 ? best[v] / scale : nothing));
        CHECK(f[2] == Approx(second[v] > -1e300 ? second[v] / scale : nothing));
        if (!(best[v] > -1e300)) CHECK(f[3] == 0.25f);
        if (second[v] > -1e300) CHECK(f[1] >= f[2]);
        CHECK(f[5] >= 0.0f);
        CHECK(f[5] <= 1.0f);
      }
    }
  }
  CHECK(candidates > 200);
  CHECK(with_vertex > 100);
}

TEST_CASE("region lookahead with the taper charge, and shortlists that keep the O-grid", "[sac][region]") {
  const auto lock = lock_general_engine();
  // Rounded polygons (arcs as chains of side vertices) and their first pieces: blocks their cuts
  // leave may taper. The charge is the search's (region_reward.h), candidate by candidate.
  std::mt19937_64 rng(1502);
  int charged = 0;
  for (int f = 0; f < 4; ++f) {
    const ArcFace arc = random_arc_face(rng, ArcKind::RoundedPolygon, 2.0);
    const Region face = input_face_from_occt(arc.face, arc.name).region;
    RegionEpisodeOptions options;
    options.reward = RewardPreset::Mesh;
    options.rules = mesh_block_rules(face.loops());
    const double size = face.bbox().longer_side();
    for (const Region& part : test::face_and_first_pieces(face, 6)) {
      if (is_block(part, options.rules)) continue;
      const RegionLookahead plain = region_look_ahead(part, size, options);
      const RegionLookahead taper = region_look_ahead(part, size, options, true);
      REQUIRE(plain.candidates.size() == taper.candidates.size());
      for (size_t k = 0; k < plain.candidates.size(); ++k) {
        const RegionCandidate& c = plain.candidates[k];
        const double charge =
            c.action.kind == RegionAction::Kind::Cut ? pieces_taper_cost(cut_region(part, c.action.cut).pieces, options.rules) : 0.0;
        CHECK(taper.candidates[k].reward == Approx(c.reward - charge).margin(1e-9));
        charged += charge > 0.0;
      }
    }
  }
  INFO("candidates charged for taper: " << charged);
  CHECK(charged >= 1);
  // The O-grid (a template on a part with a hole) is in every shortlist, whatever its reward.
  const Region plate = input_face_from_occt(plate_with_holes(10.0, 6.0, {{5.0, 3.0, 1.5}}), "plate").region;
  RegionEpisodeOptions options;
  options.reward = RewardPreset::Mesh;
  options.rules = mesh_block_rules(plate.loops());
  const RegionLookahead look = region_look_ahead(plate, 10.0, options);
  for (const size_t keep : {size_t{1}, size_t{3}}) {
    const std::vector<size_t> kept = best_candidates(look.candidates, keep);
    CHECK(std::is_sorted(kept.begin(), kept.end()));
    size_t always = 0;
    for (size_t k = 0; k < look.candidates.size(); ++k) {
      if (!look.candidates[k].always) continue;
      ++always;
      CHECK(look.candidates[k].action.kind == RegionAction::Kind::Template);
      CHECK(std::find(kept.begin(), kept.end(), k) != kept.end());
    }
    CHECK(always == 1);
    CHECK(kept.size() == keep + always);  // the O-grid's reward is far below the cuts'
  }
}
