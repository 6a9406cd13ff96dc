#include "support/catch_torch.h"

#include <cmath>
#include <cstring>

#include "core/common/error.h"
#include "core/region/block.h"
#include "core/region/region_cut.h"
#include "core/region/region_policy.h"
#include "core/sac/continuous_region_policy.h"
#include "core/sac/continuous_sac_agent.h"
#include "core/sac/paper_agent.h"
#include "core/sac/policy_file.h"
#include "core/api/policy_source.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

Region region(const Ring& outer, const std::vector<Ring>& holes = {}) { return Region(outer, holes, 1e-5); }

// Index of point p over the region's loops (region.loops() order).
int vertex_at(const Region& r, Point2 p) {
  int offset = 0;
  for (const Ring& ring : r.loops()) {
    for (size_t i = 0; i < ring.size(); ++i) {
      if (std::abs(ring[i].x - p.x) < 1e-9 && std::abs(ring[i].y - p.y) < 1e-9) return offset + static_cast<int>(i);
    }
    offset += static_cast<int>(ring.size());
  }
  FAIL("no vertex at " << p.x << ", " << p.y);
  return -1;
}

Point2 unit(Point2 d) {
  const double n = std::hypot(d.x, d.y);
  return {d.x / n, d.y / n};
}

double soft_value(std::vector<float> values, double tau) {
  double top = -1e300;
  for (const float v : values) top = std::max(top, static_cast<double>(v));
  double sum = 0;
  for (const float v : values) sum += std::exp((v - top) / tau);
  return top + tau * std::log(sum);
}

}  // namespace

TEST_CASE("the continuous action turns a share of the vertex's interior angle from its next edge", "[sac][continuous]") {
  const auto lock = lock_general_engine();
  // A 4 x 2 rectangle: at (0, 0) the next edge runs along +x, the interior angle is 90 degrees.
  const Region rect = region({{0, 0}, {4, 0}, {4, 2}, {0, 2}});
  const int corner = vertex_at(rect, {0, 0});
  const Point2 along = unit(cut_of_angle(rect, corner, -1.0).direction);
  const Point2 middle = unit(cut_of_angle(rect, corner, 0.0).direction);
  const Point2 up = unit(cut_of_angle(rect, corner, 1.0).direction);
  CHECK(along.x == Approx(1.0));
  CHECK(along.y == Approx(0.0).margin(1e-12));
  CHECK(middle.x == Approx(std::sqrt(0.5)));
  CHECK(middle.y == Approx(std::sqrt(0.5)));
  CHECK(up.x == Approx(0.0).margin(1e-12));
  CHECK(up.y == Approx(1.0));
  const RegionCut cut = cut_of_angle(rect, corner, 0.0);
  CHECK(cut.kind == CutKind::Partial);
  CHECK(cut.origin.x == 0.0);
  // The 45-degree ray ends on the top side at (2, 2): a triangle of area 2 and a trapezoid of 6.
  const CutOutcome outcome = cut_region(rect, cut);
  REQUIRE(outcome.pieces.size() == 2);
  std::vector<double> areas{outcome.pieces[0].area(), outcome.pieces[1].area()};
  std::sort(areas.begin(), areas.end());
  CHECK(areas[0] == Approx(2.0));
  CHECK(areas[1] == Approx(6.0));
  // Along an edge the cut separates nothing.
  CHECK(cut_region(rect, cut_of_angle(rect, corner, -1.0)).pieces.size() == 1);

  // The L's re-entrant corner (1, 1): 270 degrees; u = 0 turns 135 degrees from the edge to (1, 2).
  const Region l = region(test::l_shape());
  const int reflex = vertex_at(l, {1, 1});
  const Point2 bisector = unit(cut_of_angle(l, reflex, 0.0).direction);
  CHECK(bisector.x == Approx(-std::sqrt(0.5)));
  CHECK(bisector.y == Approx(-std::sqrt(0.5)));
  const Point2 first = unit(cut_of_angle(l, reflex, -1.0 / 3.0).direction);  // a third: 90 degrees
  CHECK(first.x == Approx(-1.0));
  CHECK(first.y == Approx(0.0).margin(1e-12));
  CHECK_THROWS_AS(cut_of_angle(l, 6, 0.0), std::out_of_range);
}

TEST_CASE("the continuous agent's Bellman target counts a child's template as one more choice", "[sac][continuous]") {
  const auto lock = lock_general_engine();
  torch::manual_seed(5);
  SacConfig config = default_sac_config("paper");
  config.gamma = 0.9;
  ContinuousSacAgent agent(config);
  const Region l = region(test::l_shape());
  const Region pentagon = region({{0, 0}, {4, 0}, {5, 2}, {2, 4}, {-1, 2}});
  const auto ls = general_state(l, config.graph);
  const auto ps = general_state(pentagon, config.graph);
  const float finish = template_choice_reward(pentagon, RewardPreset::Mesh, 5.0, BlockRules{});
  REQUIRE_FALSE(std::isnan(finish));
  CHECK(std::isnan(template_choice_reward(l, RewardPreset::Mesh, 5.0, BlockRules{})));  // not convex
  Transition done{ls, 2, 0, -1.5f, {}, 0.0f, {}};
  done.angle = 0.25f;
  Transition tree{ls, 1, 0, -2.0f, {ps, ls}, 0.0f, {}};
  tree.angle = -0.5f;
  tree.children_template = {finish, kNoTemplateReward};
  const double tau = agent.vertex_temperature();
  std::vector<float> with_template = agent.vertex_values(*ps);
  with_template.push_back(finish);
  const double y2 = -2.0 + 0.9 * (soft_value(with_template, tau) + soft_value(agent.vertex_values(*ls), tau));
  std::mt19937_64 rng(1);
  const auto metrics = agent.update({&done, &tree}, rng);
  CHECK(metrics.at("mean_target") == Approx((-1.5 + y2) / 2).epsilon(1e-5));
  for (const char* key : {"critic_loss", "value_loss", "actor_loss", "alpha", "tau", "angle_entropy", "vertex_entropy"}) {
    CHECK(std::isfinite(metrics.at(key)));
  }
  // Through the target critics instead: the children's terms differ, the terminal cut's does not.
  config.bootstrap = Bootstrap::Critics;
  torch::manual_seed(5);
  ContinuousSacAgent critics(config);
  const auto other = critics.update({&done, &tree}, rng);
  CHECK(std::isfinite(other.at("mean_target")));
  CHECK(other.at("mean_target") != Approx(metrics.at("mean_target")).epsilon(1e-6));
  const auto terminal = critics.update({&done}, rng);
  CHECK(terminal.at("mean_target") == Approx(-1.5));
}

TEST_CASE("the continuous actor learns the angle its critics value most", "[sac][continuous]") {
  // One part, one vertex; terminal cuts whose reward peaks at u = 0.4. The critics learn Q(o, u),
  // the reparameterised actor climbs it, the temperature holds the angle's entropy near its target.
  const auto lock = lock_general_engine();
  torch::manual_seed(9);
  SacConfig config = default_sac_config("paper");
  ContinuousSacAgent agent(config);
  const auto state = general_state(region(test::l_shape()), config.graph);
  std::mt19937_64 rng(2);
  std::vector<Transition> memory;
  for (int k = 0; k < 256; ++k) {
    Transition t{state, 2, 0, 0.0f, {}, 0.0f, {}};
    t.angle = static_cast<float>(-1.0 + 2.0 * (k + 0.5) / 256.0);
    t.reward = static_cast<float>(-8.0 * (t.angle - 0.4) * (t.angle - 0.4));
    memory.push_back(t);
  }
  const double before = agent.angle_action(state->observations[2], nullptr);
  std::uniform_int_distribution<size_t> pick(0, memory.size() - 1);
  for (int step = 0; step < 200; ++step) {
    std::vector<const Transition*> batch;
    for (int b = 0; b < 16; ++b) batch.push_back(&memory[pick(rng)]);
    agent.update(batch, rng);
  }
  const double after = agent.angle_action(state->observations[2], nullptr);
  INFO("mean action before " << before << ", after " << after);
  CHECK(std::abs(after - 0.4) < 0.15);
  CHECK(std::abs(after - 0.4) < std::abs(before - 0.4));
}

TEST_CASE("the replay buffer keeps the angle and the template rewards, and reads its first version", "[sac][continuous]") {
  const auto state = general_state(region(test::l_shape()), GraphOptions{});
  ReplayBuffer buffer(4);
  Transition t{state, 1, 0, -2.5f, {state, state}, 0.0f, {}};
  t.angle = -0.75f;
  t.children_template = {1.25f, kNoTemplateReward};
  buffer.add(t);
  const ReplayBuffer copy = ReplayBuffer::deserialize(buffer.serialize());
  REQUIRE(copy.size() == 1);
  CHECK(copy.at(0).angle == -0.75f);
  REQUIRE(copy.at(0).children_template.size() == 2);
  CHECK(copy.at(0).children_template[0] == 1.25f);
  CHECK(std::isnan(copy.at(0).children_template[1]));

  // Version 1 (before the continuous agent): no angle, no template rewards. Rewritten from version
  // 2's bytes of a grid transition without children.
  ReplayBuffer grid(2);
  grid.add(Transition{state, 3, 1, 4.5f, {}, 0.0f, {}});
  std::string bytes = grid.serialize();
  const std::uint32_t one = 1;
  std::memcpy(&bytes[4], &one, sizeof one);
  bytes.erase(bytes.size() - 8);                    // the children's template rewards (empty)
  bytes.erase(bytes.size() - 4 - 4 - 4, 4);         // the angle, before the reward and the child count
  const ReplayBuffer old = ReplayBuffer::deserialize(bytes);
  REQUIRE(old.size() == 1);
  CHECK(old.at(0).vertex == 3);
  CHECK(old.at(0).direction == 1);
  CHECK(old.at(0).reward == 4.5f);
  CHECK(old.at(0).angle == 0.0f);
  CHECK(old.at(0).children_template.empty());
  // A transition whose angle is outside [-1, 1] is corrupt.
  Transition wild{state, 1, 0, 0.0f, {}, 0.0f, {}};
  wild.angle = 3.0f;
  ReplayBuffer bad(1);
  bad.add(wild);
  CHECK_THROWS_AS(ReplayBuffer::deserialize(bad.serialize()), InputError);
}

TEST_CASE("the paper agent's policy on general faces round-trips its file, older files have none", "[sac][continuous][policy]") {
  torch::manual_seed(13);
  SacConfig config = default_sac_config("paper");
  config.reward = RewardPreset::Mesh;
  auto agent = make_learning_agent(config);
  const std::string path = test::temporary_folder("continuous-policy") + "/p.pt";
  save_policy_file(path, *agent, {}, false);
  const LoadedPolicy loaded = load_policy_file(path, false);
  const auto lock = lock_general_engine();
  RegionEpisodeOptions options;
  options.reward = RewardPreset::Mesh;
  for (int i = 0; i < 4; ++i) {
    const Region face = test::region_of(test::general_polygon(40 + i, GeneralKind::Polygon, i == 3));
    auto a = agent->deployed_region_policy("a");
    auto b = loaded.agent->deployed_region_policy("b");
    REQUIRE(a);
    REQUIRE(b);
    const RegionDecomposition da = decompose_region(face, *a, options), db = decompose_region(face, *b, options);
    CHECK(da.complete());
    CHECK(da.total_return == db.total_return);
    CHECK(da.finished.size() == db.finished.size());
    RegionEpisode episode(face, options);
    CHECK((agent->region_vertex_scores(episode) == loaded.agent->region_vertex_scores(episode)));
  }
  // sac-faithful was written before: it loads, and has no policy or scores on general faces.
  const LoadedPolicy faithful = load_policy_file(policy_file_path("sac-faithful"), false);
  CHECK_FALSE(faithful.agent->deployed_region_policy("f"));
  RegionEpisode episode(region(test::l_shape()), options);
  CHECK_THROWS_AS(faithful.agent->region_vertex_scores(episode), InputError);
  std::mt19937_64 rng(1);
  CHECK_THROWS_AS(faithful.agent->train_region_episode(region(test::l_shape()), rng, 0), InputError);
}

TEST_CASE("the paper agent's replay memory holds both buffers and reads the old single one", "[sac][continuous]") {
  torch::manual_seed(17);
  SacConfig config = default_sac_config("paper");
  config.warmup_steps = 1000;
  PaperAgent agent(config);
  std::mt19937_64 rng(3);
  agent.train_episode(test::grid_face_of(test::l_shape()), rng, 0);
  agent.train_region_episode(test::region_of(test::general_polygon(7, GeneralKind::Polygon, false)), rng, 0);
  const std::string bytes = agent.serialize_memory();
  PaperAgent copy(config);
  copy.deserialize_memory(bytes);
  CHECK(copy.serialize_memory() == bytes);
  // The old form: the grid's buffer alone.
  ReplayBuffer grid(8);
  grid.add(Transition{general_state(region(test::l_shape()), config.graph), 0, 1, 1.0f, {}, 0.0f, {}});
  PaperAgent old(config);
  old.deserialize_memory(grid.serialize());
  CHECK_THROWS_AS(old.deserialize_memory("ABPM"), InputError);
  CHECK_THROWS_AS(old.deserialize_memory(bytes.substr(0, bytes.size() / 2)), InputError);
}

TEST_CASE("a paper agent warm-started from a policy without general networks keeps its own", "[sac][continuous]") {
  torch::manual_seed(19);
  SacConfig config = default_sac_config("paper");
  auto agent = make_learning_agent(config);
  const LoadedPolicy faithful = load_policy_file(policy_file_path("sac-faithful"), false);
  agent->copy_weights_from(*faithful.agent);
  CHECK(agent->deployed_region_policy("x") != nullptr);
  const GridFace face = test::grid_face_of(test::l_shape());
  Episode episode(face);
  CHECK((agent->vertex_scores(episode) == faithful.agent->vertex_scores(episode)));
}

TEST_CASE("region_mask: the paper agent's training draws again instead of making a cut without progress",
          "[sac][continuous]") {
  // Uniform draws (the warm-up): most vertices and angles leave a piece no simpler than the part. Made,
  // they fill the episode; masked, they are remembered and drawn again, and every step made progresses.
  int steps[2] = {0, 0};
  for (const bool mask : {false, true}) {
    torch::manual_seed(23);
    SacConfig config = default_sac_config("paper");
    config.reward = RewardPreset::Mesh;
    config.warmup_steps = 100000;
    config.region_mask = mask;
    PaperAgent agent(config);
    std::mt19937_64 rng(5);
    for (int i = 0; i < 4; ++i) {
      const EpisodeRecord r =
          agent.train_region_episode(test::region_of(test::general_polygon(80 + i, GeneralKind::Polygon, i == 3)), rng, 200);
      if (mask) CHECK(r.complete);
      steps[mask] += r.steps;
    }
  }
  INFO("steps made " << steps[0] << " unmasked, " << steps[1] << " masked");
  CHECK(steps[1] < steps[0]);
}
