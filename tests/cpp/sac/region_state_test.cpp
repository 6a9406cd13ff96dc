#include "support/catch_torch.h"

#include <cmath>

#include "core/region/block.h"
#include "core/region/region_policy.h"
#include "core/sac/lookahead_agent.h"
#include "core/sac/region_state.h"
#include "core/sac/sac_config.h"
#include "support/test_shapes.h"

using namespace autoblock;

TEST_CASE("a region's state: its graph, observations and the grid's feature layout", "[sac][state][region]") {
  // Polygons and chamfered unions with and without holes, and their cut pieces: one observation per
  // vertex, in the graph's vertex order; with lookahead kLookaheadFeatures per node, the one-hot kind
  // first, the vertex summary at vertex nodes only, the part's scale at every node.
  const auto lock = lock_general_engine();
  int states = 0;
  for (int i = 0; i < 8; ++i) {
    const Region face =
        test::region_of(test::general_polygon(900 + i, i % 2 ? GeneralKind::Chamfered : GeneralKind::Polygon, i % 2 == 0));
    RegionStateOptions options;
    options.lookahead = true;
    options.episode.reward = RewardPreset::Mesh;
    options.face_size = face.bbox().longer_side();
    for (const Region& part : test::face_and_first_pieces(face, 3)) {
      if (is_block(part, options.episode.rules)) continue;
      const auto state = make_region_state(part, options);
      const RegionLookahead look = region_look_ahead(part, options.face_size, options.episode);
      REQUIRE(state->observations.size() == static_cast<size_t>(part.vertex_count()));
      REQUIRE(state->graph.vertex_nodes.size() == state->observations.size());
      REQUIRE(state->feature_count == kLookaheadFeatures);
      const size_t nodes = static_cast<size_t>(state->graph.node_count());
      REQUIRE(state->features.size() == nodes * kLookaheadFeatures);
      std::vector<int> vertex_of(nodes, -1);
      for (size_t v = 0; v < state->graph.vertex_nodes.size(); ++v) vertex_of[static_cast<size_t>(state->graph.vertex_nodes[v])] = static_cast<int>(v);
      for (size_t n = 0; n < nodes; ++n) {
        const float* row = &state->features[n * kLookaheadFeatures];
        for (int k = 0; k < 3; ++k) CHECK(row[k] == state->graph.features[n][static_cast<size_t>(k)]);
        for (int k = 0; k < kVertexLookahead; ++k) {
          const float expected = vertex_of[n] < 0 ? 0.0f : look.vertex_features[static_cast<size_t>(vertex_of[n])][static_cast<size_t>(k)];
          CHECK(row[3 + k] == expected);
        }
        for (int k = 0; k < kPartScale; ++k) CHECK(row[3 + kVertexLookahead + k] == look.scale[static_cast<size_t>(k)]);
      }
      CHECK(state->candidates.size() == look.candidates.size());
      ++states;
    }
  }
  CHECK(states > 15);
  // Without lookahead: the graph's one-hot features only, no candidates.
  const Region triangle(Ring{{0, 0}, {4, 0}, {0, 3}}, {}, 1e-9);
  const auto plain = make_region_state(triangle, RegionStateOptions{});
  CHECK(plain->feature_count == 3);
  CHECK(plain->features.empty());
  CHECK(plain->candidates.empty());
  CHECK(plain->observations.size() == 3);
}

TEST_CASE("the lookahead agent's value network values general parts, alone or batched alike", "[sac][state][region]") {
  const auto lock = lock_general_engine();
  auto agent = std::make_shared<LookaheadAgent>(default_sac_config("lookahead"));
  std::vector<std::shared_ptr<const RegionPartState>> states;
  for (int i = 0; i < 4; ++i) {
    const Region face = test::region_of(test::general_polygon(950 + i, GeneralKind::Polygon, i % 2 == 0));
    RegionStateOptions options;
    options.lookahead = true;
    options.episode.reward = RewardPreset::Mesh;
    options.face_size = face.bbox().longer_side();
    if (is_block(face, options.episode.rules)) continue;
    states.push_back(make_region_state(face, options));
  }
  REQUIRE(states.size() >= 2);
  std::vector<const PartState*> batch;
  for (const auto& s : states) batch.push_back(s.get());
  const std::vector<double> together = agent->state_values(batch);
  REQUIRE(together.size() == states.size());
  for (size_t k = 0; k < states.size(); ++k) {
    const std::vector<double> alone = agent->state_values({states[k].get()});
    CHECK(std::isfinite(together[k]));
    CHECK(alone[0] == Approx(together[k]).epsilon(1e-4));
  }
}
