#include "core/sac/continuous_sac_agent.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "core/common/error.h"
#include "core/nn/graph_batch.h"
#include "core/region/region_observation.h"
#include "core/region/region_reward.h"
#include "core/sac/region_state.h"
#include "core/sac/squashed_gaussian.h"

namespace autoblock {
namespace {

struct Squashed {
  torch::Tensor u, logp;  // the action in [-1, 1] and its log density
};

// The actor's output (mean, log std) per row; eps the standard normal draws. Reparameterised.
Squashed squash(const torch::Tensor& out, const torch::Tensor& eps) {
  const torch::Tensor mu = out.select(1, 0);
  const torch::Tensor log_std = clamped_log_std(out);
  const torch::Tensor pre = mu + log_std.exp() * eps;
  const torch::Tensor u = torch::tanh(pre);
  return {u, squashed_log_density(eps, log_std, u)};
}

// count standard normal draws from rng (not torch's generator: a resumed run repeats exactly).
torch::Tensor normal_draws(int64_t count, std::mt19937_64& rng) {
  torch::Tensor t = torch::empty({count}, torch::kFloat32);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  float* data = t.data_ptr<float>();
  for (int64_t k = 0; k < count; ++k) data[k] = normal(rng);
  return t;
}

torch::Tensor critic_input(const torch::Tensor& obs, const torch::Tensor& u) {
  return torch::cat({obs, u.unsqueeze(1)}, 1);
}

}  // namespace

float template_choice_reward(const Region& part, RewardPreset preset, double face_size, const BlockRules& rules) {
  if (is_block(part, rules) || !template_applies(part)) return kNoTemplateReward;
  return static_cast<float>(region_template_reward(preset, part, face_size, rules));
}

std::shared_ptr<const PartState> general_state(const Region& part, const GraphOptions& graph) {
  RegionStateOptions options;
  options.graph = graph;
  return make_region_state(part, options);
}

RegionCut cut_of_angle(const Region& region, int vertex, double u) {
  int loop = 0, index = vertex;
  while (loop < region.loop_count() && index >= static_cast<int>(region.loop(loop).size())) {
    index -= static_cast<int>(region.loop(loop).size());
    ++loop;
  }
  if (vertex < 0 || loop >= region.loop_count()) throw std::out_of_range("cut_of_angle: no such vertex");
  const Ring& ring = region.loop(loop);
  const size_t n = ring.size(), i = static_cast<size_t>(index);
  const Point2 v = ring[i], next = ring[(i + 1) % n];
  const double turn = 0.5 * (std::clamp(u, -1.0, 1.0) + 1.0) * region_interior_angle(region, loop, index) * M_PI / 180.0;
  const double ex = next.x - v.x, ey = next.y - v.y;
  RegionCut cut;
  cut.kind = CutKind::Partial;
  cut.origin = v;
  cut.direction = Point2{ex * std::cos(turn) - ey * std::sin(turn), ex * std::sin(turn) + ey * std::cos(turn)};
  return cut;
}

ContinuousSacAgent::ContinuousSacAgent(const SacConfig& config)
    : config_(config), nets_(config, 2, false, kObservationSize + 1, 1) {}

double ContinuousSacAgent::vertex_temperature() const { return std::exp(nets_.log_tau.item<double>()); }
double ContinuousSacAgent::angle_temperature() const { return std::exp(nets_.log_alpha.item<double>()); }

std::vector<float> ContinuousSacAgent::vertex_values(const PartState& state) { return nets_.vertex_values(state); }

double ContinuousSacAgent::angle_action(const Observation& observation, std::mt19937_64* rng) {
  torch::NoGradGuard no_grad;
  const torch::Tensor out = nets_.actor->forward(stack_observations({&observation}));
  const double mu = out[0][0].item<double>();
  if (!rng) return std::tanh(mu);
  const double log_std = std::clamp(out[0][1].item<double>(), kLogStdMin, kLogStdMax);
  // The draw comes from the caller's generator, not torch's: seeded runs repeat exactly.
  const double eps = std::normal_distribution<double>(0.0, 1.0)(*rng);
  return std::tanh(mu + std::exp(log_std) * eps);
}

torch::Tensor ContinuousSacAgent::child_values(const std::vector<const PartState*>& children,
                                               const std::vector<float>& templates, std::mt19937_64& rng) {
  torch::NoGradGuard no_grad;
  std::vector<const PartGraph*> graphs;
  for (const PartState* c : children) graphs.push_back(&c->graph);
  const GraphBatch batch = batch_graphs(graphs);
  torch::Tensor vertex_values;  // V' at every child's vertices (bootstrap "graph" only)
  if (config_.bootstrap == Bootstrap::Graph) {
    nets_.value_target->eval();
    vertex_values =
        nets_.value_target->forward(batch.x, batch.edge_index, batch.pseudo).index_select(0, batch.vertex_nodes);
  }
  const double tau = vertex_temperature();
  const double alpha = angle_temperature();
  torch::Tensor result = torch::empty({static_cast<int64_t>(children.size())}, torch::kFloat32);
  for (size_t c = 0; c < children.size(); ++c) {
    torch::Tensor values;
    if (config_.bootstrap == Bootstrap::Graph) {
      values = vertex_values.slice(0, batch.vertex_offsets[c], batch.vertex_offsets[c + 1]);
    } else {
      // Each vertex's soft value through the target critics, at one draw of the actor's angle.
      std::vector<const Observation*> observations;
      for (const Observation& o : children[c]->observations) observations.push_back(&o);
      const torch::Tensor obs = stack_observations(observations);
      const Squashed a = squash(nets_.actor->forward(obs), normal_draws(obs.size(0), rng));
      const torch::Tensor in = critic_input(obs, a.u);
      values = torch::min(nets_.q1_target->forward(in), nets_.q2_target->forward(in)).squeeze(1) - alpha * a.logp;
    }
    if (!std::isnan(templates[c])) values = torch::cat({values, torch::full({1}, templates[c])});
    result[static_cast<int64_t>(c)] = tau * torch::logsumexp(values / tau, 0);
  }
  return result;
}

std::map<std::string, double> ContinuousSacAgent::update(const std::vector<const Transition*>& batch,
                                                         std::mt19937_64& rng) {
  if (batch.empty()) throw std::logic_error("ContinuousSacAgent::update: empty batch");
  const int64_t size = static_cast<int64_t>(batch.size());
  std::vector<const Observation*> observations;
  std::vector<const PartState*> children;
  std::vector<float> templates;
  std::vector<int64_t> owners;
  torch::Tensor rewards = torch::empty({size}, torch::kFloat32);
  torch::Tensor angles = torch::empty({size}, torch::kFloat32);
  for (int64_t b = 0; b < size; ++b) {
    const Transition& t = *batch[static_cast<size_t>(b)];
    observations.push_back(&t.state->observations.at(static_cast<size_t>(t.vertex)));
    rewards[b] = t.reward;
    angles[b] = t.angle;
    for (size_t c = 0; c < t.children.size(); ++c) {
      children.push_back(t.children[c].get());
      templates.push_back(t.children_template.empty() ? std::numeric_limits<float>::quiet_NaN() : t.children_template[c]);
      owners.push_back(b);
    }
  }

  torch::Tensor target = rewards.clone();
  if (!children.empty()) {
    target.index_add_(0, torch::tensor(owners, torch::kInt64), config_.gamma * child_values(children, templates, rng));
  }
  target = target.detach();

  // Critics, at the action taken.
  const torch::Tensor obs = stack_observations(observations);
  const torch::Tensor taken = critic_input(obs, angles);
  const torch::Tensor q1 = nets_.q1->forward(taken).squeeze(1);
  const torch::Tensor q2 = nets_.q2->forward(taken).squeeze(1);
  const torch::Tensor critic_loss = torch::mse_loss(q1, target) + torch::mse_loss(q2, target);
  nets_.critic_optimizer->zero_grad();
  critic_loss.backward();
  nets_.critic_optimizer->step();

  // Value network, at the chosen vertex only.
  const SacNetworks::ValueStep value = nets_.value_step(batch, target, config_.vertex_target_entropy_fraction);

  // Actor, reparameterised through the critics (their weights not stepped here).
  const double alpha = angle_temperature();
  const Squashed a = squash(nets_.actor->forward(obs), normal_draws(size, rng));
  const torch::Tensor in = critic_input(obs, a.u);
  const torch::Tensor min_q = torch::min(nets_.q1->forward(in), nets_.q2->forward(in)).squeeze(1);
  const torch::Tensor actor_loss = (alpha * a.logp - min_q).mean();
  nets_.actor_optimizer->zero_grad();
  actor_loss.backward();
  nets_.actor_optimizer->step();
  nets_.critic_optimizer->zero_grad();  // the actor's pass left gradients on the critics

  // Temperatures, with the entropies held fixed.
  const double angle_entropy = -a.logp.mean().item<double>();
  nets_.temperature_step(angle_entropy, config_.angle_target_entropy, value);

  nets_.blend_targets(config_.polyak);

  return {{"value_loss", value.loss},
          {"critic_loss", critic_loss.item<double>()},
          {"actor_loss", actor_loss.item<double>()},
          {"alpha", angle_temperature()},
          {"tau", vertex_temperature()},
          {"angle_entropy", angle_entropy},
          {"vertex_entropy", value.vertex_entropy},
          {"mean_target", target.mean().item<double>()},
          {"mean_q", q1.mean().item<double>()}};
}

void ContinuousSacAgent::save(torch::serialize::OutputArchive& archive, const std::string& prefix, bool training) const {
  nets_.save(archive, prefix, training);
}

void ContinuousSacAgent::load(torch::serialize::InputArchive& archive, const std::string& prefix, bool training) {
  nets_.load(archive, prefix, training);
}

}  // namespace autoblock
