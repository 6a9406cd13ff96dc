// Actor-proposed candidates for the lookahead agent on general faces (issue 12, item 2): cuts that no
// fixed candidate list holds.
//
// The lookahead agent chooses among a part's candidate actions (region_candidates.h: edge
// extensions, bisectors, normals, the minimum rectangle's axes, diagonals): a few exact directions
// per vertex. With SacConfig::actor_candidates = k > 0 an actor refines the best of them: at each
// of the k distinct vertices the best candidates by reward start at (best_at_vertices,
// region_lookahead.h), it takes the best listed cut from that vertex and proposes the same cut
// (kind and origin) turned by u * kProposalTilt radians, u in [-1, 1]: a direction between the
// listed ones, which no fixed list holds. A proposal that makes progress is a candidate like the
// others, valued Q = reward + gamma * sum of W(pieces); one that does not is dropped.
//
// The actor: 11 numbers (proposal_input: the vertex's 9-number observation, region_observation.h,
// and the listed cut's direction as cosine and sine from the vertex's next edge) -> 128 -> 64 ->
// (mu, log std); u = tanh(mu + sigma eps) in training, tanh(mu) deployed (the squashed Gaussian of
// the paper's agent's angle).
//
// Learning, from exact action values. A proposal's value is known at the step it is made: the
// environment cuts it and the value network values its pieces, Q(u) (a proposal without progress,
// never taken, counts as the worst listed candidate's Q). There is no critic to learn: the actor
// follows the score-function gradient of the maximum-entropy objective E[Q(u) / s] + alpha H,
//   loss = -mean over proposals of (A - alpha log pi(u)) * log pi(u),   A = (Q(u) - b) / s,
// with b the Q of the listed cut it turns: a baseline that does not depend on u, so the gradient is
// unbiased, and A > 0 exactly when the turned cut beats the listed one. s is the reward scale. alpha
// is tuned towards SacConfig::angle_target_entropy as SAC's temperature. One step per training
// episode, on that episode's proposals (on-policy; nothing is left pending between episodes, so a
// resumed run repeats exactly).
#pragma once

#include <array>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <torch/torch.h>

#include "core/env/observation.h"
#include "core/geometry/point.h"
#include "core/nn/mlp.h"
#include "core/region/region_cut.h"
#include "core/sac/sac_config.h"

namespace autoblock {

constexpr double kProposalTilt = 0.3;  // radians (17 degrees): the most a proposal turns a listed cut
constexpr int kProposalInputs = kObservationSize + 2;
using ProposalInput = std::array<float, kProposalInputs>;

// Inputs:  observation, at the vertex; next_edge, the vertex's edge to the next vertex of its loop;
//          direction, the listed cut's. Output: the actor's input (above).
ProposalInput proposal_input(const Observation& observation, Point2 next_edge, Point2 direction);

// Inputs: cut; u in [-1, 1]. Output: the cut turned counter-clockwise by u * kProposalTilt about its origin.
RegionCut turned_cut(const RegionCut& cut, double u);

class CutProposer {
 public:
  // Inputs: config (lr_actor, lr_temperature, initial_direction_temperature, angle_target_entropy).
  //         The caller seeds torch (initial weights).
  explicit CutProposer(const SacConfig& config);

  struct Draw {
    double z = 0.0;  // the Gaussian's draw before tanh (mu when deployed)
    double u = 0.0;  // tanh(z), in [-1, 1]
  };
  // Inputs: inputs, one per cut to turn; rng: draws (training), or null: the mean (deployed).
  Draw draw(const ProposalInput& input, std::mt19937_64* rng);
  std::vector<Draw> draw(const std::vector<const ProposalInput*>& inputs, std::mt19937_64* rng);

  struct Sample {
    ProposalInput input;
    double z = 0.0;
    double advantage = 0.0;  // (Q(u) - b) / s, see above
  };
  // One gradient step of the actor and its temperature on samples (not empty). Output: named metrics
  // (proposal_loss, proposal_alpha, proposal_entropy, proposal_advantage).
  std::map<std::string, double> update(const std::vector<Sample>& samples);
  double temperature() const;

  // Under the keys "proposal_actor", "proposal_log_alpha" (training: "proposal_optimizer" too).
  void save(torch::serialize::OutputArchive& archive, bool training) const;
  // Output: false when the archive holds no proposer (a policy trained without one: the weights stay
  //         as they are); throws on a malformed one.
  bool load(torch::serialize::InputArchive& archive, bool training);

 private:
  SacConfig config_;
  Mlp actor_{nullptr};
  torch::Tensor log_alpha_;
  std::unique_ptr<torch::optim::Adam> actor_optimizer_, temperature_optimizer_;
};

}  // namespace autoblock
