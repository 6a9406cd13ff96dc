// The networks and temperatures of a Soft Actor-Critic agent with a graph value network, shared by
// the paper's agent on grid faces (sac_agent.h: two discrete directions) and on general faces
// (continuous_sac_agent.h: a continuous angle): the value network over a part's graph and its
// target, an actor and twin critics (9 or 10 -> 256 -> 128 -> 64 -> outputs) on the local
// observation with the critics' targets, the temperatures alpha (the cut's choice) and tau (the
// vertex's), and their optimisers.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <torch/torch.h>

#include "core/env/observation.h"
#include "core/nn/mlp.h"
#include "core/nn/value_network.h"
#include "core/sac/part_state.h"
#include "core/sac/replay_buffer.h"
#include "core/sac/sac_config.h"

namespace autoblock {

// Inputs: observations. Output: a (count x 9) tensor of them.
torch::Tensor stack_observations(const std::vector<const Observation*>& observations);

struct SacNetworks {
  // Inputs: config (value network preset, learning rates, initial temperatures); the actor's
  //         outputs and whether a ReLU follows its output layer; the critics' inputs and outputs.
  //         The caller seeds torch (the order of construction fixes the initial weights).
  SacNetworks(const SacConfig& config, int64_t actor_outputs, bool actor_output_relu, int64_t critic_inputs,
              int64_t critic_outputs);

  // Values of the value network at the part's model vertices (evaluation mode, no gradient).
  std::vector<float> vertex_values(const PartState& state);
  // Moves every target network this fraction of the way to its online network.
  void blend_targets(double fraction);

  struct ValueStep {
    double loss = 0.0;            // (V(P, v) - y)^2 at the chosen vertices, before the step
    double vertex_entropy = 0.0;  // mean entropy of softmax(V(P, .) / tau) over the batch
    double vertex_target = 0.0;   // its target: fraction x ln(number of vertices), averaged
  };
  // One step of the value network at the batch's chosen vertices towards target (one per
  // transition; gradients clipped to norm 10), as the paper: only the chosen vertex learns.
  ValueStep value_step(const std::vector<const Transition*>& batch, const torch::Tensor& target,
                       double vertex_target_entropy_fraction);
  // One step of both temperatures with the entropies held fixed: alpha towards choice_target, tau
  // towards the value step's vertex target.
  void temperature_step(double choice_entropy, double choice_target, const ValueStep& value);

  // Under prefix + the keys ("value", "actor", "q1", "q2", "log_alpha", "log_tau"; training: the
  // targets and the optimisers too). Loading without training sets the targets to the online networks.
  void save(torch::serialize::OutputArchive& archive, const std::string& prefix, bool training) const;
  void load(torch::serialize::InputArchive& archive, const std::string& prefix, bool training);

  ValueNetwork value{nullptr}, value_target{nullptr};
  Mlp actor{nullptr}, q1{nullptr}, q2{nullptr}, q1_target{nullptr}, q2_target{nullptr};
  torch::Tensor log_alpha, log_tau;
  std::unique_ptr<torch::optim::Adam> value_optimizer, critic_optimizer, actor_optimizer, temperature_optimizer;
};

}  // namespace autoblock
