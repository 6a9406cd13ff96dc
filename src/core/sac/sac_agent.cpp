#include "core/sac/sac_agent.h"

#include <cmath>
#include <stdexcept>

#include "core/nn/graph_batch.h"

namespace autoblock {

SacAgent::SacAgent(const SacConfig& config)
    : config_(config), nets_(config, 2, config.actor_output_relu, kObservationSize, 2) {}

double SacAgent::vertex_temperature() const { return std::exp(nets_.log_tau.item<double>()); }
double SacAgent::direction_temperature() const { return std::exp(nets_.log_alpha.item<double>()); }

std::vector<float> SacAgent::vertex_values(const PartState& state) { return nets_.vertex_values(state); }

std::array<float, 2> SacAgent::direction_probabilities(const Observation& observation) {
  torch::NoGradGuard no_grad;
  const torch::Tensor p = torch::softmax(nets_.actor->forward(stack_observations({&observation})), 1).contiguous();
  return {p.data_ptr<float>()[0], p.data_ptr<float>()[1]};
}

torch::Tensor SacAgent::child_values(const std::vector<const PartState*>& children) {
  torch::NoGradGuard no_grad;
  std::vector<const PartGraph*> graphs;
  for (const PartState* c : children) graphs.push_back(&c->graph);
  const GraphBatch batch = batch_graphs(graphs);
  nets_.value_target->eval();
  const torch::Tensor vertex_values =
      nets_.value_target->forward(batch.x, batch.edge_index, batch.pseudo).index_select(0, batch.vertex_nodes);
  const double tau = vertex_temperature();
  const double alpha = direction_temperature();
  torch::Tensor result = torch::empty({static_cast<int64_t>(children.size())}, torch::kFloat32);
  for (size_t c = 0; c < children.size(); ++c) {
    const torch::Tensor values = vertex_values.slice(0, batch.vertex_offsets[c], batch.vertex_offsets[c + 1]);
    if (config_.bootstrap == Bootstrap::Graph) {
      result[static_cast<int64_t>(c)] = tau * torch::logsumexp(values / tau, 0);
    } else {
      std::vector<const Observation*> observations;
      for (const Observation& o : children[c]->observations) observations.push_back(&o);
      const torch::Tensor obs = stack_observations(observations);
      const torch::Tensor min_q = torch::min(nets_.q1_target->forward(obs), nets_.q2_target->forward(obs));
      const torch::Tensor logp = torch::log_softmax(nets_.actor->forward(obs), 1);
      const torch::Tensor soft_q = (logp.exp() * (min_q - alpha * logp)).sum(1);  // per vertex
      const torch::Tensor vertex_logp = torch::log_softmax(values / tau, 0);
      const torch::Tensor pv = vertex_logp.exp();
      result[static_cast<int64_t>(c)] = (pv * soft_q).sum() - tau * (pv * vertex_logp).sum();
    }
  }
  return result;
}

std::map<std::string, double> SacAgent::update(const std::vector<const Transition*>& batch) {
  if (batch.empty()) throw std::logic_error("SacAgent::update: empty batch");
  const int64_t size = static_cast<int64_t>(batch.size());
  std::vector<const Observation*> observations;
  std::vector<const PartState*> children;
  std::vector<int64_t> owners;
  torch::Tensor rewards = torch::empty({size}, torch::kFloat32);
  torch::Tensor actions = torch::empty({size}, torch::kInt64);
  for (int64_t b = 0; b < size; ++b) {
    const Transition& t = *batch[static_cast<size_t>(b)];
    observations.push_back(&t.state->observations.at(static_cast<size_t>(t.vertex)));
    rewards[b] = t.reward;
    actions[b] = static_cast<int64_t>(t.direction);
    for (const auto& c : t.children) {
      children.push_back(c.get());
      owners.push_back(b);
    }
  }

  // Bellman targets over the tree: y = r + gamma * sum of the children's soft values.
  torch::Tensor target = rewards.clone();
  if (!children.empty()) {
    const torch::Tensor w = child_values(children);
    target.index_add_(0, torch::tensor(owners, torch::kInt64), config_.gamma * w);
  }
  target = target.detach();

  // Critics.
  const torch::Tensor obs = stack_observations(observations);
  const torch::Tensor a = actions.unsqueeze(1);
  const torch::Tensor q1 = nets_.q1->forward(obs).gather(1, a).squeeze(1);
  const torch::Tensor q2 = nets_.q2->forward(obs).gather(1, a).squeeze(1);
  const torch::Tensor critic_loss = torch::mse_loss(q1, target) + torch::mse_loss(q2, target);
  nets_.critic_optimizer->zero_grad();
  critic_loss.backward();
  nets_.critic_optimizer->step();

  // Value network, at the chosen vertex only.
  const SacNetworks::ValueStep value = nets_.value_step(batch, target, config_.vertex_target_entropy_fraction);

  // Actor.
  const double alpha = direction_temperature();
  const torch::Tensor logp = torch::log_softmax(nets_.actor->forward(obs), 1);
  const torch::Tensor p = logp.exp();
  torch::Tensor min_q;
  {
    torch::NoGradGuard no_grad;
    min_q = torch::min(nets_.q1->forward(obs), nets_.q2->forward(obs));
  }
  const torch::Tensor actor_loss = (p * (alpha * logp - min_q)).sum(1).mean();
  nets_.actor_optimizer->zero_grad();
  actor_loss.backward();
  nets_.actor_optimizer->step();

  // Temperatures, with the entropies held fixed.
  const double direction_entropy = -(p * logp).sum(1).mean().item<double>();
  nets_.temperature_step(direction_entropy, config_.direction_target_entropy, value);

  nets_.blend_targets(config_.polyak);

  return {{"value_loss", value.loss},
          {"critic_loss", critic_loss.item<double>()},
          {"actor_loss", actor_loss.item<double>()},
          {"alpha", direction_temperature()},
          {"tau", vertex_temperature()},
          {"direction_entropy", direction_entropy},
          {"vertex_entropy", value.vertex_entropy},
          {"mean_target", target.mean().item<double>()},
          {"mean_q", q1.mean().item<double>()}};
}

void SacAgent::save(torch::serialize::OutputArchive& archive, bool training) const {
  nets_.save(archive, "", training);
}

void SacAgent::load(torch::serialize::InputArchive& archive, bool training) { nets_.load(archive, "", training); }

}  // namespace autoblock
