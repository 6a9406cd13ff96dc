#include "core/sac/sac_agent.h"

#include <cmath>
#include <stdexcept>

#include "core/nn/graph_batch.h"
#include "core/nn/module_blend.h"

namespace autoblock {
namespace {

constexpr int64_t kObservation = kObservationSize;
const std::vector<int64_t> kHidden{256, 128, 64};

torch::Tensor stack_observations(const std::vector<const Observation*>& observations) {
  torch::Tensor t = torch::empty({static_cast<int64_t>(observations.size()), kObservation}, torch::kFloat32);
  float* data = t.data_ptr<float>();
  for (size_t b = 0; b < observations.size(); ++b) {
    for (int k = 0; k < kObservationSize; ++k) data[b * kObservationSize + static_cast<size_t>(k)] = (*observations[b])[static_cast<size_t>(k)];
  }
  return t;
}

// Entropy of softmax(values / temperature).
torch::Tensor softmax_entropy(const torch::Tensor& values, double temperature) {
  const torch::Tensor logp = torch::log_softmax(values / temperature, 0);
  return -(logp.exp() * logp).sum();
}

}  // namespace

SacAgent::SacAgent(const SacConfig& config) : config_(config) {
  const ValueNetworkConfig value_config = ValueNetworkConfig::by_name(config.value_network);
  value_ = ValueNetwork(value_config);
  value_target_ = ValueNetwork(value_config);
  actor_ = Mlp(kObservation, kHidden, 2, config.actor_output_relu);
  q1_ = Mlp(kObservation, kHidden, 2, false);
  q2_ = Mlp(kObservation, kHidden, 2, false);
  q1_target_ = Mlp(kObservation, kHidden, 2, false);
  q2_target_ = Mlp(kObservation, kHidden, 2, false);
  blend_module(*value_target_, *value_, 1.0);
  blend_module(*q1_target_, *q1_, 1.0);
  blend_module(*q2_target_, *q2_, 1.0);
  value_target_->eval();
  log_alpha_ = torch::full({}, std::log(config.initial_direction_temperature), torch::requires_grad());
  log_tau_ = torch::full({}, std::log(config.initial_vertex_temperature), torch::requires_grad());
  value_optimizer_ = std::make_unique<torch::optim::Adam>(value_->parameters(), torch::optim::AdamOptions(config.lr_value));
  std::vector<torch::Tensor> critic_parameters = q1_->parameters();
  for (const auto& p : q2_->parameters()) critic_parameters.push_back(p);
  critic_optimizer_ = std::make_unique<torch::optim::Adam>(critic_parameters, torch::optim::AdamOptions(config.lr_critic));
  actor_optimizer_ = std::make_unique<torch::optim::Adam>(actor_->parameters(), torch::optim::AdamOptions(config.lr_actor));
  temperature_optimizer_ = std::make_unique<torch::optim::Adam>(std::vector<torch::Tensor>{log_alpha_, log_tau_},
                                                                torch::optim::AdamOptions(config.lr_temperature));
}

double SacAgent::vertex_temperature() const { return std::exp(log_tau_.item<double>()); }
double SacAgent::direction_temperature() const { return std::exp(log_alpha_.item<double>()); }

std::vector<float> SacAgent::vertex_values(const PartState& state) {
  torch::NoGradGuard no_grad;
  value_->eval();
  const GraphBatch batch = batch_graphs({&state.graph});
  const torch::Tensor values =
      value_->forward(batch.x, batch.edge_index, batch.pseudo).index_select(0, batch.vertex_nodes).contiguous();
  return std::vector<float>(values.data_ptr<float>(), values.data_ptr<float>() + values.numel());
}

std::array<float, 2> SacAgent::direction_probabilities(const Observation& observation) {
  torch::NoGradGuard no_grad;
  const torch::Tensor p = torch::softmax(actor_->forward(stack_observations({&observation})), 1).contiguous();
  return {p.data_ptr<float>()[0], p.data_ptr<float>()[1]};
}

torch::Tensor SacAgent::child_values(const std::vector<const PartState*>& children) {
  torch::NoGradGuard no_grad;
  std::vector<const PartGraph*> graphs;
  for (const PartState* c : children) graphs.push_back(&c->graph);
  const GraphBatch batch = batch_graphs(graphs);
  value_target_->eval();
  const torch::Tensor vertex_values =
      value_target_->forward(batch.x, batch.edge_index, batch.pseudo).index_select(0, batch.vertex_nodes);
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
      const torch::Tensor min_q = torch::min(q1_target_->forward(obs), q2_target_->forward(obs));
      const torch::Tensor logp = torch::log_softmax(actor_->forward(obs), 1);
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
  std::vector<const PartGraph*> graphs;
  std::vector<const Observation*> observations;
  std::vector<const PartState*> children;
  std::vector<int64_t> owners;
  torch::Tensor rewards = torch::empty({size}, torch::kFloat32);
  torch::Tensor actions = torch::empty({size}, torch::kInt64);
  for (int64_t b = 0; b < size; ++b) {
    const Transition& t = *batch[static_cast<size_t>(b)];
    graphs.push_back(&t.state->graph);
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
  const torch::Tensor q1 = q1_->forward(obs).gather(1, a).squeeze(1);
  const torch::Tensor q2 = q2_->forward(obs).gather(1, a).squeeze(1);
  const torch::Tensor critic_loss = torch::mse_loss(q1, target) + torch::mse_loss(q2, target);
  critic_optimizer_->zero_grad();
  critic_loss.backward();
  critic_optimizer_->step();

  // Value network, at the chosen vertex only.
  const GraphBatch parents = batch_graphs(graphs);
  value_->train();
  const torch::Tensor node_values = value_->forward(parents.x, parents.edge_index, parents.pseudo);
  std::vector<int64_t> chosen_rows;
  for (int64_t b = 0; b < size; ++b) chosen_rows.push_back(parents.vertex_offsets[static_cast<size_t>(b)] + batch[static_cast<size_t>(b)]->vertex);
  const torch::Tensor vertex_values = node_values.index_select(0, parents.vertex_nodes);
  const torch::Tensor chosen = vertex_values.index_select(0, torch::tensor(chosen_rows, torch::kInt64));
  const torch::Tensor value_loss = torch::mse_loss(chosen, target);
  value_optimizer_->zero_grad();
  value_loss.backward();
  torch::nn::utils::clip_grad_norm_(value_->parameters(), 10.0);
  value_optimizer_->step();

  // Actor.
  const double alpha = direction_temperature();
  const torch::Tensor logp = torch::log_softmax(actor_->forward(obs), 1);
  const torch::Tensor p = logp.exp();
  torch::Tensor min_q;
  {
    torch::NoGradGuard no_grad;
    min_q = torch::min(q1_->forward(obs), q2_->forward(obs));
  }
  const torch::Tensor actor_loss = (p * (alpha * logp - min_q)).sum(1).mean();
  actor_optimizer_->zero_grad();
  actor_loss.backward();
  actor_optimizer_->step();

  // Temperatures, with the entropies held fixed.
  const double direction_entropy = -(p * logp).sum(1).mean().item<double>();
  const double tau = vertex_temperature();
  double vertex_entropy = 0.0, vertex_target = 0.0;
  {
    torch::NoGradGuard no_grad;
    const torch::Tensor detached = vertex_values.detach();
    for (int64_t b = 0; b < size; ++b) {
      const int64_t from = parents.vertex_offsets[static_cast<size_t>(b)], to = parents.vertex_offsets[static_cast<size_t>(b) + 1];
      vertex_entropy += softmax_entropy(detached.slice(0, from, to), tau).item<double>();
      vertex_target += config_.vertex_target_entropy_fraction * std::log(static_cast<double>(to - from));
    }
    vertex_entropy /= static_cast<double>(size);
    vertex_target /= static_cast<double>(size);
  }
  const torch::Tensor temperature_loss = log_alpha_.exp() * (direction_entropy - config_.direction_target_entropy) +
                                         log_tau_.exp() * (vertex_entropy - vertex_target);
  temperature_optimizer_->zero_grad();
  temperature_loss.backward();
  temperature_optimizer_->step();

  blend_module(*value_target_, *value_, config_.polyak);
  blend_module(*q1_target_, *q1_, config_.polyak);
  blend_module(*q2_target_, *q2_, config_.polyak);

  return {{"value_loss", value_loss.item<double>()},
          {"critic_loss", critic_loss.item<double>()},
          {"actor_loss", actor_loss.item<double>()},
          {"alpha", direction_temperature()},
          {"tau", vertex_temperature()},
          {"direction_entropy", direction_entropy},
          {"vertex_entropy", vertex_entropy},
          {"mean_target", target.mean().item<double>()},
          {"mean_q", q1.mean().item<double>()}};
}

void SacAgent::save(torch::serialize::OutputArchive& archive, bool training) const {
  auto put = [&archive](const std::string& key, const torch::nn::Module& module) {
    torch::serialize::OutputArchive sub;
    module.save(sub);
    archive.write(key, sub);
  };
  put("value", *value_);
  put("actor", *actor_);
  put("q1", *q1_);
  put("q2", *q2_);
  archive.write("log_alpha", log_alpha_.detach());
  archive.write("log_tau", log_tau_.detach());
  if (!training) return;
  put("value_target", *value_target_);
  put("q1_target", *q1_target_);
  put("q2_target", *q2_target_);
  auto put_optimizer = [&archive](const std::string& key, const torch::optim::Optimizer& optimizer) {
    torch::serialize::OutputArchive sub;
    optimizer.save(sub);
    archive.write(key, sub);
  };
  put_optimizer("value_optimizer", *value_optimizer_);
  put_optimizer("critic_optimizer", *critic_optimizer_);
  put_optimizer("actor_optimizer", *actor_optimizer_);
  put_optimizer("temperature_optimizer", *temperature_optimizer_);
}

void SacAgent::load(torch::serialize::InputArchive& archive, bool training) {
  auto get = [&archive](const std::string& key, torch::nn::Module& module) {
    torch::serialize::InputArchive sub;
    archive.read(key, sub);
    module.load(sub);
  };
  get("value", *value_);
  get("actor", *actor_);
  get("q1", *q1_);
  get("q2", *q2_);
  torch::Tensor log_alpha, log_tau;
  archive.read("log_alpha", log_alpha);
  archive.read("log_tau", log_tau);
  {
    torch::NoGradGuard no_grad;
    log_alpha_.copy_(log_alpha);
    log_tau_.copy_(log_tau);
  }
  if (!training) {
    blend_module(*value_target_, *value_, 1.0);
    blend_module(*q1_target_, *q1_, 1.0);
    blend_module(*q2_target_, *q2_, 1.0);
    return;
  }
  get("value_target", *value_target_);
  get("q1_target", *q1_target_);
  get("q2_target", *q2_target_);
  auto get_optimizer = [&archive](const std::string& key, torch::optim::Optimizer& optimizer) {
    torch::serialize::InputArchive sub;
    archive.read(key, sub);
    optimizer.load(sub);
  };
  get_optimizer("value_optimizer", *value_optimizer_);
  get_optimizer("critic_optimizer", *critic_optimizer_);
  get_optimizer("actor_optimizer", *actor_optimizer_);
  get_optimizer("temperature_optimizer", *temperature_optimizer_);
}

}  // namespace autoblock
