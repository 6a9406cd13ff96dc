#include "core/sac/sac_networks.h"

#include <cmath>

#include "core/nn/graph_batch.h"
#include "core/nn/module_blend.h"
#include "core/sac/squashed_gaussian.h"

namespace autoblock {
namespace {
const std::vector<int64_t> kHidden{256, 128, 64};
}  // namespace

torch::Tensor stack_observations(const std::vector<const Observation*>& observations) {
  return stack_rows(observations);
}

SacNetworks::SacNetworks(const SacConfig& config, int64_t actor_outputs, bool actor_output_relu, int64_t critic_inputs,
                         int64_t critic_outputs) {
  const ValueNetworkConfig value_config = ValueNetworkConfig::by_name(config.value_network);
  value = ValueNetwork(value_config);
  value_target = ValueNetwork(value_config);
  actor = Mlp(kObservationSize, kHidden, actor_outputs, actor_output_relu);
  q1 = Mlp(critic_inputs, kHidden, critic_outputs, false);
  q2 = Mlp(critic_inputs, kHidden, critic_outputs, false);
  q1_target = Mlp(critic_inputs, kHidden, critic_outputs, false);
  q2_target = Mlp(critic_inputs, kHidden, critic_outputs, false);
  blend_targets(1.0);
  value_target->eval();
  log_alpha = torch::full({}, std::log(config.initial_direction_temperature), torch::requires_grad());
  log_tau = torch::full({}, std::log(config.initial_vertex_temperature), torch::requires_grad());
  value_optimizer = std::make_unique<torch::optim::Adam>(value->parameters(), torch::optim::AdamOptions(config.lr_value));
  std::vector<torch::Tensor> critic_parameters = q1->parameters();
  for (const auto& p : q2->parameters()) critic_parameters.push_back(p);
  critic_optimizer = std::make_unique<torch::optim::Adam>(critic_parameters, torch::optim::AdamOptions(config.lr_critic));
  actor_optimizer = std::make_unique<torch::optim::Adam>(actor->parameters(), torch::optim::AdamOptions(config.lr_actor));
  temperature_optimizer = std::make_unique<torch::optim::Adam>(std::vector<torch::Tensor>{log_alpha, log_tau},
                                                               torch::optim::AdamOptions(config.lr_temperature));
}

std::vector<float> SacNetworks::vertex_values(const PartState& state) {
  torch::NoGradGuard no_grad;
  value->eval();
  const GraphBatch batch = batch_graphs({&state.graph});
  const torch::Tensor values =
      value->forward(batch.x, batch.edge_index, batch.pseudo).index_select(0, batch.vertex_nodes).contiguous();
  return std::vector<float>(values.data_ptr<float>(), values.data_ptr<float>() + values.numel());
}

void SacNetworks::blend_targets(double fraction) {
  blend_module(*value_target, *value, fraction);
  blend_module(*q1_target, *q1, fraction);
  blend_module(*q2_target, *q2, fraction);
}

SacNetworks::ValueStep SacNetworks::value_step(const std::vector<const Transition*>& batch, const torch::Tensor& target,
                                               double vertex_target_entropy_fraction) {
  std::vector<const PartGraph*> graphs;
  std::vector<int64_t> chosen_rows;
  for (const Transition* t : batch) graphs.push_back(&t->state->graph);
  const GraphBatch parents = batch_graphs(graphs);
  for (size_t b = 0; b < batch.size(); ++b) chosen_rows.push_back(parents.vertex_offsets[b] + batch[b]->vertex);
  value->train();
  const torch::Tensor node_values = value->forward(parents.x, parents.edge_index, parents.pseudo);
  const torch::Tensor vertex_values = node_values.index_select(0, parents.vertex_nodes);
  const torch::Tensor chosen = vertex_values.index_select(0, torch::tensor(chosen_rows, torch::kInt64));
  const torch::Tensor loss = torch::mse_loss(chosen, target);
  value_optimizer->zero_grad();
  loss.backward();
  torch::nn::utils::clip_grad_norm_(value->parameters(), 10.0);
  value_optimizer->step();

  ValueStep step;
  step.loss = loss.item<double>();
  torch::NoGradGuard no_grad;
  const double tau = std::exp(log_tau.item<double>());
  const torch::Tensor detached = vertex_values.detach();
  for (size_t b = 0; b < batch.size(); ++b) {
    const int64_t from = parents.vertex_offsets[b], to = parents.vertex_offsets[b + 1];
    const torch::Tensor logp = torch::log_softmax(detached.slice(0, from, to) / tau, 0);
    step.vertex_entropy -= (logp.exp() * logp).sum().item<double>();
    step.vertex_target += vertex_target_entropy_fraction * std::log(static_cast<double>(to - from));
  }
  step.vertex_entropy /= static_cast<double>(batch.size());
  step.vertex_target /= static_cast<double>(batch.size());
  return step;
}

void SacNetworks::temperature_step(double choice_entropy, double choice_target, const ValueStep& value_step) {
  const torch::Tensor loss = log_alpha.exp() * (choice_entropy - choice_target) +
                             log_tau.exp() * (value_step.vertex_entropy - value_step.vertex_target);
  temperature_optimizer->zero_grad();
  loss.backward();
  temperature_optimizer->step();
}

void SacNetworks::save(torch::serialize::OutputArchive& archive, const std::string& prefix, bool training) const {
  auto put = [&](const std::string& key, const torch::nn::Module& module) {
    torch::serialize::OutputArchive sub;
    module.save(sub);
    archive.write(prefix + key, sub);
  };
  put("value", *value);
  put("actor", *actor);
  put("q1", *q1);
  put("q2", *q2);
  archive.write(prefix + "log_alpha", log_alpha.detach());
  archive.write(prefix + "log_tau", log_tau.detach());
  if (!training) return;
  put("value_target", *value_target);
  put("q1_target", *q1_target);
  put("q2_target", *q2_target);
  auto put_optimizer = [&](const std::string& key, const torch::optim::Optimizer& optimizer) {
    torch::serialize::OutputArchive sub;
    optimizer.save(sub);
    archive.write(prefix + key, sub);
  };
  put_optimizer("value_optimizer", *value_optimizer);
  put_optimizer("critic_optimizer", *critic_optimizer);
  put_optimizer("actor_optimizer", *actor_optimizer);
  put_optimizer("temperature_optimizer", *temperature_optimizer);
}

void SacNetworks::load(torch::serialize::InputArchive& archive, const std::string& prefix, bool training) {
  auto get = [&](const std::string& key, torch::nn::Module& module) {
    torch::serialize::InputArchive sub;
    archive.read(prefix + key, sub);
    module.load(sub);
  };
  get("value", *value);
  get("actor", *actor);
  get("q1", *q1);
  get("q2", *q2);
  torch::Tensor alpha, tau;
  archive.read(prefix + "log_alpha", alpha);
  archive.read(prefix + "log_tau", tau);
  {
    torch::NoGradGuard no_grad;
    log_alpha.copy_(alpha);
    log_tau.copy_(tau);
  }
  if (!training) {
    blend_targets(1.0);
    return;
  }
  get("value_target", *value_target);
  get("q1_target", *q1_target);
  get("q2_target", *q2_target);
  auto get_optimizer = [&](const std::string& key, torch::optim::Optimizer& optimizer) {
    torch::serialize::InputArchive sub;
    archive.read(prefix + key, sub);
    optimizer.load(sub);
  };
  get_optimizer("value_optimizer", *value_optimizer);
  get_optimizer("critic_optimizer", *critic_optimizer);
  get_optimizer("actor_optimizer", *actor_optimizer);
  get_optimizer("temperature_optimizer", *temperature_optimizer);
}

}  // namespace autoblock
