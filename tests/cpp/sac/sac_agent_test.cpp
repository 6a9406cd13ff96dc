#include "support/catch_torch.h"

#include <cmath>

#include "core/env/reward.h"
#include "core/sac/sac_agent.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

double soft_value(const std::vector<float>& values, double tau) {
  double top = -1e300;
  for (float v : values) top = std::max(top, static_cast<double>(v));
  double sum = 0;
  for (float v : values) sum += std::exp((v - top) / tau);
  return top + tau * std::log(sum);
}

}  // namespace

TEST_CASE("SAC losses on a tiny hand-made batch match their formulas", "[sac]") {
  torch::manual_seed(7);
  SacConfig config;
  config.gamma = 0.9;
  SacAgent agent(config);
  const auto l = make_part_state(test::grid_face_of(test::l_shape()).whole, config.graph);
  const auto u = make_part_state(test::grid_face_of({{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}).whole,
                                 config.graph);
  // Transition 1: cut the L at its re-entrant corner (vertex 3) vertically, reward 10.28, done.
  // Transition 2: a cut of the U that left two children (the L, twice, for the arithmetic).
  Transition done{l, 3, 1, 10.28f, {}, 0.0f, {}};
  Transition tree{u, 4, 0, 5.58f, {l, l}, 0.0f, {}};
  // Before the update the target networks equal the online ones: W(L) = tau logsumexp(V(L)/tau).
  const double tau = agent.vertex_temperature();
  const double w = soft_value(agent.vertex_values(*l), tau);
  const double y1 = 10.28, y2 = 5.58 + 0.9 * (w + w);
  const double mean_target = (y1 + y2) / 2;
  const auto metrics = agent.update({&done, &tree});
  CHECK(metrics.at("mean_target") == Approx(mean_target).epsilon(1e-5));
  CHECK(metrics.at("critic_loss") >= 0);
  CHECK(metrics.at("value_loss") >= 0);
  for (const char* key : {"actor_loss", "alpha", "tau", "direction_entropy", "vertex_entropy", "mean_q"}) {
    CHECK(std::isfinite(metrics.at(key)));
  }
}

TEST_CASE("the critics' loss is the squared error against the Bellman target", "[sac]") {
  torch::manual_seed(3);
  SacConfig config;
  SacAgent agent(config);
  const auto l = make_part_state(test::grid_face_of(test::l_shape()).whole, config.graph);
  // Terminal transitions only: y = r. The critics are fresh: Q_i(o)[a] are their outputs now.
  Transition a{l, 3, 1, 4.0f, {}, 0.0f, {}}, b{l, 0, 0, -3.0f, {}, 0.0f, {}};
  const auto metrics = agent.update({&a, &b});
  // Mean of y over the batch.
  CHECK(metrics.at("mean_target") == Approx(0.5));
  // Repeated updates on the same batch drive the critics' error down.
  double last = metrics.at("critic_loss");
  for (int k = 0; k < 200; ++k) last = agent.update({&a, &b}).at("critic_loss");
  CHECK(last < 0.1 * metrics.at("critic_loss"));
}

TEST_CASE("the temperatures move towards their target entropies", "[sac]") {
  torch::manual_seed(5);
  SacConfig config;
  config.direction_target_entropy = 0.05;  // far below the initial ~ln 2: alpha must fall
  SacAgent agent(config);
  const auto l = make_part_state(test::grid_face_of(test::l_shape()).whole, config.graph);
  Transition a{l, 3, 1, 4.0f, {}, 0.0f, {}};
  const double alpha0 = agent.direction_temperature();
  for (int k = 0; k < 50; ++k) agent.update({&a});
  CHECK(agent.direction_temperature() < alpha0);
}

namespace {

// The actor's probability of a vertical cut at the L's re-entrant corner after `updates` SAC
// updates on one terminal transition per direction there (rewards: horizontal, vertical).
double p_vertical_after(SacAgent& agent, const std::shared_ptr<const PartState>& l, float horizontal, float vertical,
                        int updates) {
  Transition h{l, 3, 0, horizontal, {}, 0.0f, {}}, v{l, 3, 1, vertical, {}, 0.0f, {}};
  for (int k = 0; k < updates; ++k) agent.update({&h, &v});
  return agent.direction_probabilities(l->observations[3])[1];
}

}  // namespace

TEST_CASE("an actor whose logits pass through a ReLU dies, a linear one follows the critics", "[sac]") {
  // The paper's text puts a ReLU after every actor layer, the output included. The losing
  // direction's logit is pushed below zero, where the ReLU has no gradient; when the critics later
  // prefer that direction, the winning logit is pushed down to zero too and the actor is uniform
  // for good (measured in training: the direction entropy was exactly ln 2 on every batch from
  // episode 62 on). Without the output ReLU the actor follows the critics, also when they change.
  const auto l = make_part_state(test::grid_face_of(test::l_shape()).whole, GraphOptions{});
  for (const bool relu : {true, false}) {
    INFO("actor_output_relu = " << relu);
    torch::manual_seed(11);
    SacConfig config = default_sac_config("paper");
    config.actor_output_relu = relu;
    SacAgent agent(config);
    const double vertical_better = p_vertical_after(agent, l, -5.0f, 10.0f, 300);
    const double horizontal_better = p_vertical_after(agent, l, 10.0f, -5.0f, 600);
    if (relu) {
      // Both logits dead: uniform, whatever the critics say, and stuck there.
      CHECK(horizontal_better == Approx(0.5).margin(1e-6));
      CHECK(p_vertical_after(agent, l, -5.0f, 10.0f, 300) == Approx(0.5).margin(1e-6));
    } else {
      CHECK(vertical_better > 0.95);
      CHECK(horizontal_better < 0.05);
    }
  }
  CHECK_FALSE(default_sac_config("paper").actor_output_relu);  // the default is the linear output
}
