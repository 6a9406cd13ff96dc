#include "support/catch_torch.h"

#include <cmath>
#include <random>

#include "core/common/error.h"
#include "core/region/region_policy.h"
#include "core/region/region_symmetry.h"
#include "core/sac/lookahead_agent.h"
#include "core/sac/region_lookahead.h"
#include "core/sac/sac_config.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

SacConfig mesh_config() {
  SacConfig config = default_sac_config("lookahead");
  config.reward = RewardPreset::Mesh;
  config.train_top_k = 5;
  return config;
}

}  // namespace

TEST_CASE("the lookahead agent's target on a general part is the soft maximum over its best actions, by hand",
          "[sac][lookahead][region]") {
  torch::manual_seed(12);
  auto agent = std::make_shared<LookaheadAgent>(mesh_config());
  const Region face = test::region_of(test::general_polygon(1300, GeneralKind::Polygon, false));
  const double face_size = face.bbox().longer_side();
  const BlockRules rules = mesh_block_rules(face.loops());
  double expected = 0.0;
  {
    const auto lock = lock_general_engine();
    const auto state = make_region_state(face, agent->region_state_options(face_size, rules));
    const std::vector<size_t> actions = best_candidates(state->candidates, 5);
    REQUIRE(actions.size() == std::min<size_t>(5, state->candidates.size()));
    REQUIRE(actions.size() >= 2);
    // The same actions as region_action_values values; y = alpha log sum exp(Q / alpha).
    const std::vector<double> q = agent->region_action_values(*state, actions, face_size, rules);
    const double alpha = agent->temperature();
    double sum = 0.0;
    for (size_t k = 0; k < actions.size(); ++k) {
      const RegionCandidate& c = state->candidates[actions[k]];
      double value = c.reward;
      for (const Region& piece : c.to_cut) {
        const auto p = make_region_state(piece, agent->region_state_options(face_size, rules));
        value += agent->state_values({p.get()})[0];
      }
      CHECK(q[k] == Approx(value).epsilon(1e-5));
      sum += std::exp(value / alpha);
    }
    expected = alpha * std::log(sum);
  }
  agent->remember_region(face, face_size, rules, 0.0, false);
  std::mt19937_64 rng(3);
  const auto metrics = agent->update(1, rng);  // takes the lock itself
  CHECK(metrics.at("mean_target") == Approx(expected).epsilon(1e-5));
  CHECK(std::isfinite(metrics.at("value_loss")));
}

TEST_CASE("trained on a general part shown at random angles, the value network agrees across angles",
          "[sac][lookahead][region]") {
  // One part remembered in 16 views (turns and mirrors): after regression every view's value is
  // about the same, and near the target. The augmentation teaches the invariance at any angle.
  torch::manual_seed(13);
  auto agent = std::make_shared<LookaheadAgent>(mesh_config());
  const Region face = test::region_of(test::general_polygon(1301, GeneralKind::Polygon, false));
  const double face_size = face.bbox().longer_side();
  const BlockRules rules = mesh_block_rules(face.loops());
  std::mt19937_64 rng(4);
  for (int k = 0; k < 16; ++k) agent->remember_region(face, face_size, rules, 0.4 * k, k % 2 == 1);
  double target = 0.0;
  for (int k = 0; k < 300; ++k) target = agent->update(8, rng).at("mean_target");
  std::vector<double> w;
  {
    const auto lock = lock_general_engine();
    for (const double angle : {0.1, 1.3, 2.9, 4.4}) {  // angles it was not shown at
      for (const bool mirror : {false, true}) {
        const auto s = make_region_state(transform_region(face, angle, mirror), agent->region_state_options(face_size, rules));
        w.push_back(agent->state_values({s.get()})[0]);
      }
    }
  }
  INFO("target " << target);
  for (const double v : w) CHECK(v == Approx(target).margin(0.15 * std::abs(target) + 0.5));
}

TEST_CASE("a replay memory with general parts survives its bytes, old and corrupt bytes", "[sac][lookahead][region]") {
  torch::manual_seed(14);
  auto agent = std::make_shared<LookaheadAgent>(mesh_config());
  const Region face = test::region_of(test::general_polygon(1302, GeneralKind::Chamfered, true));
  const GridFace grid = test::grid_face_of({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  const BlockRules rules = mesh_block_rules(face.loops());
  agent->remember(grid.whole, grid.size, 3);
  agent->remember_region(face, 123.5, rules, 1.25, true);
  const std::string bytes = agent->serialize_memory();
  auto other = std::make_shared<LookaheadAgent>(mesh_config());
  other->deserialize_memory(bytes);
  CHECK(other->memory_size() == 2);
  CHECK(other->serialize_memory() == bytes);  // the same parts, face sizes, rules and views
  // The same batches give the same targets.
  std::mt19937_64 a(5), b(5);
  torch::manual_seed(15);
  auto first = std::make_shared<LookaheadAgent>(mesh_config());
  torch::manual_seed(15);
  auto second = std::make_shared<LookaheadAgent>(mesh_config());
  first->deserialize_memory(bytes);
  second->deserialize_memory(other->serialize_memory());
  CHECK(first->update(4, a).at("mean_target") == second->update(4, b).at("mean_target"));
  // Truncated bytes, and a wrong grid size, are refused with an InputError.
  CHECK_THROWS_AS(other->deserialize_memory(bytes.substr(0, bytes.size() - 5)), InputError);
  std::string bad = bytes;
  bad[4 + 8] = 7;  // after the magic (4 bytes) and the grid count (8): the first grid's column count
  CHECK_THROWS_AS(other->deserialize_memory(bad), InputError);
}

TEST_CASE("a training episode on a general face ends in blocks and remembers its parts", "[sac][lookahead][region]") {
  torch::manual_seed(16);
  SacConfig config = mesh_config();
  config.warmup_steps = 3;
  config.batch_size = 4;
  auto agent = std::make_shared<LookaheadAgent>(config);
  std::mt19937_64 rng(6);
  for (int k = 0; k < 3; ++k) {
    const Region face = test::region_of(test::general_polygon(1310 + k, GeneralKind::Polygon, k == 2));
    const EpisodeRecord record = agent->train_region_episode(face, rng, 0);
    CHECK(record.complete);
    CHECK(record.blocks >= 1);
    CHECK(record.steps >= 1);
  }
  CHECK(agent->memory_size() >= 3);
  CHECK(agent->deployed_region_policy("x") != nullptr);
}

TEST_CASE("region_taper: off by default and in files without it, on, the agent's general states carry the charge",
          "[sac][lookahead][region][config]") {
  SacConfig config = mesh_config();
  CHECK_FALSE(config.region_taper);
  nlohmann::json j = sac_config_json(config);
  j.erase("region_taper");
  CHECK_FALSE(sac_config_from_json(j).region_taper);
  config = with_settings(config, {"region_taper=true"});
  CHECK(sac_config_from_json(sac_config_json(config)).region_taper);
  auto agent = std::make_shared<LookaheadAgent>(config);
  CHECK(agent->region_state_options(10.0, BlockRules{}).taper);
  config.reward = RewardPreset::Paper;  // the charge is the mesh preset's
  CHECK_FALSE(std::make_shared<LookaheadAgent>(config)->region_state_options(10.0, BlockRules{}).taper);
  CHECK_FALSE(std::make_shared<LookaheadAgent>(mesh_config())->region_state_options(10.0, BlockRules{}).taper);
}
