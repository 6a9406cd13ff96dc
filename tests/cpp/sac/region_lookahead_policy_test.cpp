#include "support/catch_torch.h"

#include <algorithm>
#include <random>

#include "core/data/arc_generator.h"
#include "core/io/input_face.h"
#include "core/region/block.h"
#include "core/sac/region_lookahead_policy.h"
#include "core/sac/sac_config.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("the lookahead agent on general faces: Q by hand, every face finished, the same twice", "[sac][region]") {
  // An untrained agent (its value network is random; what is checked is the policy's arithmetic and
  // that it ends every face in blocks): polygons and chamfered unions with and without holes, and
  // faces with arcs, under both presets.
  const auto lock = lock_general_engine();
  SacConfig config = default_sac_config("lookahead");
  config.reward = RewardPreset::Mesh;
  auto agent = std::make_shared<LookaheadAgent>(config);
  std::vector<Region> faces;
  for (int i = 0; i < 3; ++i) {
    faces.push_back(test::region_of(test::general_polygon(1200 + i, i % 2 ? GeneralKind::Chamfered : GeneralKind::Polygon, i == 2)));
  }
  std::mt19937_64 rng(1201);
  for (const ArcKind kind : {ArcKind::PlateHoles, ArcKind::RoundedPolygon}) {
    const ArcFace arc_face = random_arc_face(rng, kind, 3.0);
    faces.push_back(input_face_from_occt(arc_face.face, arc_face.name).region);
  }
  int checked = 0;
  for (const Region& face : faces) {
    RegionEpisodeOptions options;
    options.reward = RewardPreset::Mesh;
    const double face_size = face.bbox().longer_side();
    if (!is_block(face, options.rules)) {
      // The first choice is the argmax of reward + gamma * sum of W over the pieces left to cut.
      RegionLookaheadPolicy policy(agent, "sac-mesh");
      const auto state = make_region_state(face, policy.state_options(options, face_size));
      REQUIRE_FALSE(state->candidates.empty());
      const std::vector<double> q = policy.action_values(*state, options, face_size);
      REQUIRE(q.size() == state->candidates.size());
      for (size_t k = 0; k < q.size(); ++k) {
        const RegionCandidate& c = state->candidates[k];
        std::vector<std::shared_ptr<const RegionPartState>> pieces;
        std::vector<const PartState*> batch;
        for (const Region& piece : c.to_cut) {
          pieces.push_back(make_region_state(piece, policy.state_options(options, face_size)));
          batch.push_back(pieces.back().get());
        }
        double expected = c.reward;
        if (!batch.empty()) {
          for (const double w : agent->deployed_values(batch)) expected += config.gamma * w;
        }
        CHECK(q[k] == Approx(expected).epsilon(1e-4).margin(1e-5));  // one float rounding apart: batched and not
        ++checked;
      }
      // Deployed with top k: the k best candidates by reward, in the candidates' order.
      agent->set_deploy_top_k(3);
      const std::vector<size_t> three = policy.shortlist(*state);
      REQUIRE(three.size() == std::min<size_t>(3, state->candidates.size()));
      for (size_t j = 1; j < three.size(); ++j) CHECK(three[j - 1] < three[j]);
      int above = 0;  // candidates left out with a higher reward than one kept
      for (size_t k = 0; k < state->candidates.size(); ++k) {
        if (std::find(three.begin(), three.end(), k) != three.end()) continue;
        for (const size_t kept : three) above += state->candidates[k].reward > state->candidates[kept].reward;
      }
      CHECK(above == 0);
      agent->set_deploy_top_k(0);
      CHECK(policy.shortlist(*state).size() == state->candidates.size());
    }
    RegionLookaheadPolicy first(agent, "sac-mesh"), second(agent, "sac-mesh");
    const RegionDecomposition a = decompose_region(face, first, options), b = decompose_region(face, second, options);
    CHECK(a.complete());
    REQUIRE(a.cuts.size() == b.cuts.size());
    for (size_t k = 0; k < a.cuts.size(); ++k) {
      CHECK(a.cuts[k].action.cut.origin == b.cuts[k].action.cut.origin);
      CHECK(a.cuts[k].action.cut.direction == b.cuts[k].action.cut.direction);
    }
  }
  CHECK(checked > 30);
}
