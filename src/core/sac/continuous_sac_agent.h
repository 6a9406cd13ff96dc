// The paper's Soft Actor-Critic with a continuous action, for general faces (issue 12): the cut's
// angle is a real number.
//
// Acting on a part P of a general face (paper_agent.h drives it):
//   the vertex  drawn from softmax(V(P, .) / tau) over P's vertices (all its loops, in
//               region.loops() order), V the value network over P's graph (region_graph.h). When
//               the template (block.h) finishes P, it is one more choice, valued by its reward: it
//               ends the part, so its value is known exactly and nothing is learned about it;
//   the angle   u = tanh(mu(o_v) + sigma(o_v) * eps), eps ~ N(0, 1): a squashed Gaussian over
//               [-1, 1] from the actor on the vertex's 9-number observation (region_observation.h).
//               The cut is the partial cut (region_cut.h) from v along the direction that turns
//               (u + 1) / 2 of v's interior angle counter-clockwise from the edge to the next vertex
//               (the part lies on that edge's left): every u points into the part, u -> -1 and
//               u -> 1 run along v's two edges. See cut_of_angle.
// Deployed: the vertex (or template) of highest value and u = tanh(mu).
//
// Learning (one update per cut after the warm-up; the same tree Bellman target as the grid's
// agent, sac_agent.h):
//   y = r + gamma * sum over the cut's children c of W'(c),
//   W'(c) = tau * logsumexp over c's choices of (V'(c, v) or the template's reward) / tau,
//   critics     (Q_i(o_v, u) - y)^2, twin, each 10 -> 256 -> 128 -> 64 -> 1, Polyak-averaged targets;
//               with bootstrap "critics" a vertex's term in W'(c) is min_i Q'_i(o_v, u) - alpha log pi(u | o_v)
//               at one draw u of the actor instead of V'(c, v) (the default, "graph", uses V');
//   value       (V(P, v) - y)^2 at the chosen vertex only, as the paper;
//   actor       reparameterised: E[alpha log pi(u | o) - min_i Q_i(o, u)], u = tanh(mu + sigma eps),
//               log pi(u) = log N(eps) - sum log(1 - u^2) (SAC's tanh correction);
//   temperatures alpha towards the angle's target entropy (angle_target_entropy, -1 nats: -dim(A),
//               SAC's usual choice) and tau towards the vertex choice's (vertex_target_entropy_fraction
//               of ln(number of choices)), with the entropies held fixed.
#pragma once

#include <limits>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <torch/torch.h>

#include "core/region/block.h"
#include "core/region/region.h"
#include "core/region/region_cut.h"
#include "core/graph/region_graph.h"
#include "core/sac/replay_buffer.h"
#include "core/sac/sac_config.h"
#include "core/sac/sac_networks.h"

namespace autoblock {

// Inputs:  region, not empty; vertex, an index over its loops' vertices in region.loops() order; u in
//          [-1, 1].
// Outputs: the partial cut from that vertex turned (u + 1) / 2 of its interior angle counter-clockwise
//          from its edge to the next vertex (see above).
RegionCut cut_of_angle(const Region& region, int vertex, double u);

// A template choice's value where the template does not apply.
constexpr float kNoTemplateReward = std::numeric_limits<float>::quiet_NaN();

// Inputs:  part; preset; face_size; rules. Output: the reward of finishing part with the template
//          (its value as a choice), kNoTemplateReward where it is a block or the template does not
//          apply.
float template_choice_reward(const Region& part, RewardPreset preset, double face_size, const BlockRules& rules);

// Inputs: part, not empty; graph. Output: what the continuous agent sees of it (region_state.h,
//         without lookahead).
std::shared_ptr<const PartState> general_state(const Region& part, const GraphOptions& graph);

class ContinuousSacAgent {
 public:
  // Inputs: config. The caller seeds torch for reproducible initial weights.
  explicit ContinuousSacAgent(const SacConfig& config);

  // Values of the value network at the part's vertices (evaluation mode, no gradient).
  std::vector<float> vertex_values(const PartState& state);
  // The actor's squashed action at an observation: drawn (rng) or, without rng, its mean tanh(mu).
  double angle_action(const Observation& observation, std::mt19937_64* rng);
  double vertex_temperature() const;
  double angle_temperature() const;

  // One gradient step of every network and both temperatures, then the targets' Polyak step; the
  // actor's noise comes from rng.
  // Output: named metrics (value_loss, critic_loss, actor_loss, alpha, tau, angle_entropy,
  // vertex_entropy, mean_target, mean_q).
  std::map<std::string, double> update(const std::vector<const Transition*>& batch, std::mt19937_64& rng);

  // Under prefix + key, as SacAgent::save / load (training: targets and optimisers too).
  void save(torch::serialize::OutputArchive& archive, const std::string& prefix, bool training) const;
  void load(torch::serialize::InputArchive& archive, const std::string& prefix, bool training);

 private:
  torch::Tensor child_values(const std::vector<const PartState*>& children, const std::vector<float>& templates,
                             std::mt19937_64& rng);

  SacConfig config_;
  SacNetworks nets_;
};

}  // namespace autoblock
