// Discrete Soft Actor-Critic for block decomposition (DiPrete et al. 2022), with the episode's tree
// of parts made explicit in the Bellman target.
//
// Networks (as the paper): a value network (graph network over the part's triangulation) giving a
// value at every model vertex; an actor and twin critics (9 -> 256 -> 128 -> 64 -> 2) on the local
// observation at a vertex; target copies of the value network and the critics (Polyak averaged).
// The actor's output layer is linear, its softmax the direction probabilities. The paper's text
// puts a ReLU after every actor layer, the output included (config.actor_output_relu); with it
// the losing direction's logit is pushed below zero, where it has no gradient, and once the
// critics change their mind the other logit follows: both are zero for every observation, the
// actor is uniform for good and, deployed, always cuts horizontally (ties). Measured (issue 15,
// BENCHMARKS.md): the direction entropy was exactly ln 2 on every batch from episode 62 on and
// the deterministic test return stayed at 22.8, below a random choice among splitting cuts.
//
// Acting. The vertex is drawn from softmax(V(P, .) / tau) over the part's model vertices (training)
// or is the argmax (deployed); the direction is drawn from the actor's pi(. | o_v) (training) or its
// argmax. tau (vertex temperature) and alpha (direction temperature) are both tuned automatically
// towards target entropies: for the direction, 0.3 nats (ln 2 = 0.69 is the maximum with two
// actions; SAC's usual 0.98 ln |A| asks for an almost uniform policy and makes alpha grow without
// bound); for the vertex, 0.3 ln(number of vertices).
//
// The tree. A cut of P leaves pieces; each non-rectangular piece c is cut on later (FIFO), so the
// return that follows the cut is the cut's reward plus the returns of *all* its children, not of one
// next state. The Bellman target of a cut (P, v, a) -> r, children C is therefore
//   y = r + gamma * sum over c in C of W(c)        (W = 0 for rectangles; C = {P} when N = 1)
// where W(c) is the soft value of part c: with the target value network V',
//   bootstrap "graph":   W(c) = tau * logsumexp(V'(c, .) / tau)
//                              = E_{v ~ softmax(V'/tau)} V'(c, v) + tau * H(vertex choice),
//   bootstrap "critics": W(c) = E_v [ E_{a ~ pi}(min_i Q'_i(o_v, a) - alpha log pi(a | o_v)) ] + tau H,
//                        with the vertex distribution softmax(V'(c, .) / tau).
// "graph" carries the value network's view of the whole part into the target; "critics" is the
// SAC-v2 form through the target critics. Both are implemented; the choice is measured (see the
// training report) and stored in the configuration.
// Losses on a batch: critics (Q_i(o_v, a) - y)^2; value network only at the chosen vertex, as the
// paper says, (V(P, v) - y)^2; actor sum_a pi(a|o)(alpha log pi(a|o) - min_i Q_i(o, a)); the
// temperatures alpha (H(pi) - target) and tau (H(vertex choice) - target) with entropies held fixed.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <torch/torch.h>

#include "core/sac/replay_buffer.h"
#include "core/sac/sac_config.h"
#include "core/sac/sac_networks.h"

namespace autoblock {

class SacAgent {
 public:
  // Inputs: config. The caller seeds torch (torch::manual_seed) for reproducible initial weights.
  explicit SacAgent(const SacConfig& config);

  const SacConfig& config() const { return config_; }

  // Values of the value network at the part's model vertices (evaluation mode, no gradient).
  std::vector<float> vertex_values(const PartState& state);
  // The actor's probabilities of (horizontal, vertical) at an observation.
  std::array<float, 2> direction_probabilities(const Observation& observation);
  double vertex_temperature() const;
  double direction_temperature() const;

  // One gradient step of every network and both temperatures on the batch, then the target
  // networks' Polyak step. Output: named metrics (value_loss, critic_loss, actor_loss, alpha,
  // tau, direction_entropy, vertex_entropy, mean_target, mean_q).
  std::map<std::string, double> update(const std::vector<const Transition*>& batch);

  // Inputs: archive; training, true to include target networks, optimisers and temperatures'
  // optimiser (a checkpoint), false for what deployment needs (a policy).
  void save(torch::serialize::OutputArchive& archive, bool training) const;
  void load(torch::serialize::InputArchive& archive, bool training);

 private:
  // Soft values W(c) of the given child states (no gradient).
  torch::Tensor child_values(const std::vector<const PartState*>& children);

  SacConfig config_;
  SacNetworks nets_;
};

}  // namespace autoblock
