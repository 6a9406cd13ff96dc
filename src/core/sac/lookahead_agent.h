// The lookahead agent: maximum-entropy (soft) reinforcement learning, as SAC, with a one-cut
// lookahead in place of the learned local actor and critics. Going beyond the paper.
//
// Why. The paper's direction actor and critics see 9 numbers at one vertex: they cannot tell where
// a full cut ends or what it leaves, and its value network must guess both the cut and everything
// after it. Measured with exact targets (supervised, 37 training faces), that design reaches about
// 0.8 of the optimal return on unseen faces. The environment, though, is known and exact: a cut's
// reward and pieces cost microseconds. So this agent looks one cut ahead and learns only what
// follows.
//
// Networks. One value network (the paper's SplineCNN, node features: the 3 one-hot kinds, per-vertex
// lookahead summaries and the part's scale, see part_state.h) gives the soft value of a part,
//   W(P) = s * sum over P's model vertices of the network's output   (s: the reward scale),
// and W = 0 for a rectangle. A target copy W' is refreshed every target_update_every updates.
//
// Acting. Every distinct cut L through a corner of P that splits it has
//   Q(P, L) = reward(P, L) + gamma * sum of W(pieces left to cut),
// and the policy is the maximum-entropy one for these values: pi(L | P) = softmax(Q(P, .) / alpha)
// in training (uniform during the warm-up), argmax when deployed. The cut is made at the line's
// first corner, so a vertex and a direction are chosen, as in the paper; cuts that change nothing
// are never candidates.
//
// Learning. Remembered parts are revisited with the soft Bellman target over all their cuts,
//   y(P) = alpha * logsumexp_L(Q'(P, L) / alpha)       (Q' with W'),
// the value loss is ((W(P) - y) / s)^2, and alpha is tuned like SAC's temperature towards an
// entropy of vertex_target_entropy_fraction * ln(number of cuts). The tree of parts is handled by
// the sum over the pieces. Each remembered part is presented in one of the square's eight
// symmetries (rewards and values do not change under them), which multiplies the training data.
//
// Deployed (LookaheadPolicy below), a piece's value is the mean over deploy_views symmetric views
// of it; with bounded graphs (part_graph.h) a view is the piece's graph transformed
// (symmetric_view), not a second triangulation. Within a decomposition nothing is done twice: a
// part's state (graph, lookahead) and a piece's value are kept, keyed by the part (its cells on the
// face's grid, which identify it within one face), and the pieces a step has not valued yet go
// through the network as one batch.
//
// Pruned deployment (deploy_top_k = k > 0, issue 8): the network's forward pass over the pieces of
// every cut is nearly all of a learned decomposition's time, so only the pieces of the k cuts with
// the best two-step score
//   S(P, L) = reward(P, L) + gamma * sum over its pieces Q left to cut of E(Q),
//   E(Q) = (the best reward of one cut of Q) * max(1, (r + 1) / 2), r = Q's reflex corners
// are valued (ties: the earlier cut), and the argmax is taken among them. E is a guess at what is
// left to earn from Q without its graph or the network: its best next cut's reward times about the
// number of cuts Q still needs (a cut through a reflex corner removes one or two of them). Measured
// on validation faces (BENCHMARKS.md) it keeps the network's choice much better than the immediate
// reward or the best next reward alone, which prefer cuts that finish pieces early. S is a function
// of the part alone, so the decisions do not depend on what the caches hold; with k at least the
// number of cuts the decisions are those of the unpruned policy. Training values every cut (its
// soft Bellman target is over all cuts: W learns the value of the whole maximum-entropy policy); a
// policy file records its deploy_top_k, and files without one (every policy before this) value
// every cut.
//
// General faces (issue 12). The same learning on parts of general faces (region engine): a part's
// actions are its candidates (region_lookahead.h) with the train_top_k best rewards, valued as
//   Q(P, a) = reward(P, a) + gamma * sum of W(pieces a leaves that are not blocks),
// acted on by softmax(Q / alpha) (uniform among them in the warm-up), and remembered parts are
// revisited with the soft Bellman target over those actions. The deployed policy on general faces is
// RegionLookaheadPolicy (region_lookahead_policy.h). Rewards and blocks follow the agent's preset and
// the face's rules (mesh_block_rules under the mesh preset); with region_taper (sac_config.h) and the
// mesh preset a candidate's reward is less the taper charge of the blocks it leaves (region_reward.h),
// as the search ranks and values cuts. Augmentation: a remembered general part
// is shown turned by a random angle and mirrored at random (region_symmetry.h), with its face's size
// and rules kept: candidates, rewards and blocks do not depend on the frame, so its target holds for
// every view (the face's bounding box, which a turn changes, only sets the scale, and the scale is
// the remembered face's). The network thus learns the invariance under every rotation, not only the
// square's eight. Grid and general parts share one memory and one network; a batch may mix them.
// States and target values of general parts are kept keyed by the part, its face's size and rules.
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

#include <torch/torch.h>

#include "core/nn/value_network.h"
#include "core/sac/cut_proposer.h"
#include "core/sac/learning_agent.h"
#include "core/sac/part_state.h"
#include "core/sac/region_state.h"

namespace autoblock {

class LookaheadAgent;

// The deployed policy: argmax of Q over the candidate cuts (see above), with caches of the states
// it built and of the pieces' values (a cut's pieces are the next parts to cut). Owns no training
// state; one per thread and per decomposition (its caches grow with the parts it meets).
class LookaheadPolicy : public Policy {
 public:
  LookaheadPolicy(std::shared_ptr<LookaheadAgent> agent, std::string name);
  std::string name() const override { return name_; }
  Action choose(const Episode& episode) override;

  // Q(P, L) for every candidate cut of state (a lookahead state of this policy's face); a piece's
  // value is the mean of the network's values over deploy_views symmetric views of it, computed
  // once per piece. Cuts outside the shortlist (pruned deployment) get minus infinity.
  std::vector<double> values(const PartState& state, double face_size);
  // The indices (increasing) of the cuts of state whose pieces the network values: all of them, or
  // with deploy_top_k = k > 0 the k best by the two-step score S (see above).
  std::vector<size_t> shortlist(const PartState& state, double face_size);
  // The part's lookahead state, built once.
  std::shared_ptr<const PartState> state_of(const Part& part, double face_size);
  size_t valued_pieces() const { return values_.size(); }

 private:
  std::shared_ptr<LookaheadAgent> agent_;
  std::string name_;
  bool reuse_values_ = true;
  std::unordered_map<Part, std::shared_ptr<const PartState>, PartHash> states_;
  std::unordered_map<Part, std::shared_ptr<const PartState>, PartHash> refined_views_[8];  // refined graphs only
  std::unordered_map<Part, double, PartHash> values_;  // W of pieces, mean over the views
  std::unordered_map<Part, double, PartHash> estimates_;  // pruning: E of pieces (see above)
  double piece_estimate(const Part& piece, double face_size);
};

class LookaheadAgent : public LearningAgent {
 public:
  explicit LookaheadAgent(const SacConfig& config);

  const SacConfig& config() const override { return config_; }
  EpisodeRecord train_episode(const GridFace& face, std::mt19937_64& rng, int max_steps) override;
  EpisodeRecord train_region_episode(const Region& face, std::mt19937_64& rng, int max_steps) override;
  std::unique_ptr<RegionPolicy> deployed_region_policy(const std::string& name) override;
  std::vector<float> region_vertex_scores(const RegionEpisode& episode) override;
  void set_training_progress(double fraction) override;
  void prepare_checkpoint() override;  // the target values' caches
  std::unique_ptr<Policy> deployed_policy(const std::string& name) override;
  std::vector<float> vertex_scores(const Episode& episode) override;
  void save(torch::serialize::OutputArchive& archive, bool training) const override;
  void load(torch::serialize::InputArchive& archive, bool training) override;
  std::string serialize_memory() const override;
  void deserialize_memory(const std::string& bytes) override;

  PartStateOptions state_options(double face_size) const;
  // The options of a general part's state as this agent reads it: lookahead, the agent's reward
  // preset, the face's size and block rules.
  RegionStateOptions region_state_options(double face_size, const BlockRules& rules) const;
  // Inputs: state, a general part's (region_state_options); which, indices of its candidates.
  // Output: Q of those candidates (online network, evaluation mode, no gradient). The caller holds
  //         lock_general_engine() (region_policy.h).
  std::vector<double> region_action_values(const RegionPartState& state, const std::vector<size_t>& which,
                                           double face_size, const BlockRules& rules);
  // The same for any candidates of a part (listed or proposed).
  std::vector<double> candidate_values(const std::vector<const RegionCandidate*>& candidates, double face_size,
                                       const BlockRules& rules);

  // Actor-proposed candidates (cut_proposer.h; SacConfig::actor_candidates > 0).
  struct ProposedCut {
    int vertex = -1;
    size_t base = 0;        // the listed candidate it turns (index into the state's candidates)
    ProposalInput input{};  // what the actor saw
    CutProposer::Draw draw;
    std::optional<RegionCandidate> candidate;  // nothing: no progress (dropped)
  };
  // Inputs:  part, not a block; state, its (region_state_options); face_size; rules; rng: drawn
  //          (training) or null: the actor's mean (deployed). The caller holds lock_general_engine().
  // Outputs: one proposal per candidate of best_at_vertices(state.candidates, actor_candidates): the
  //          best listed cut from its vertex, turned by the actor's angle; none without a proposer.
  std::vector<ProposedCut> propose_cuts(const Region& part, const RegionPartState& state, double face_size,
                                        const BlockRules& rules, std::mt19937_64* rng);
  bool proposes() const { return proposer_ != nullptr; }
  CutProposer* proposer() { return proposer_.get(); }
  // Q(P, L) for every candidate cut of the state (online network, evaluation mode, no gradient).
  std::vector<double> cut_values(const PartState& state, double face_size);
  // W of the given states (online network, evaluation mode, no gradient), in return units.
  std::vector<double> state_values(const std::vector<const PartState*>& states);
  // The same with the deployed network (the weight average when weight_average_decay > 0).
  std::vector<double> deployed_values(const std::vector<const PartState*>& states);
  double temperature() const;
  // Overrides the configuration's deploy_views (1 to 8) of this agent's deployed policies.
  void set_deploy_views(int views) { config_.deploy_views = std::max(1, std::min(8, views)); }
  // Overrides the configuration's deploy_top_k (0: every cut) of this agent's deployed policies.
  void set_deploy_top_k(int k) { config_.deploy_top_k = std::max(0, k); }
  // Overrides the configuration's region_taper (mesh preset, general faces: candidates charged for
  // the search's taper) in training and deployment from now on (for benchmarks and ablations).
  void set_region_taper(bool taper) { config_.region_taper = taper; }
  // Whether this agent's deployed policies keep the pieces' values from step to step (default
  // true). Off, every step values all its pieces again, as before issue 8 (for benchmarks).
  void set_deploy_reuse(bool reuse) { deploy_reuse_ = reuse; }
  bool deploy_reuse() const { return deploy_reuse_; }
  // The value network's current learning rate (set_training_progress moves it).
  double learning_rate() const;

  // One gradient step on `count` remembered parts, then the target refresh when due. Output:
  // named metrics (value_loss, alpha, entropy, mean_target).
  std::map<std::string, double> update(size_t count, std::mt19937_64& rng);
  size_t memory_size() const { return memory_.size(); }
  // Inputs: part, its face's size, the symmetry it is presented in (0..7). Remembers it.
  void remember(const Part& part, double face_size, int symmetry);
  // Inputs: part, of a general face, not a block; its face's size and block rules; how it is shown
  //         (region_symmetry.h: angle in radians, mirror). Remembers it.
  void remember_region(const Region& part, double face_size, const BlockRules& rules, double angle, bool mirror);

 private:
  struct Memory {
    Part part;            // a grid part, or
    Region region;        // a general one (not empty)
    double face_size = 1.0;
    int symmetry = 0;     // grid: part_symmetry.h
    BlockRules rules;     // general: the face's
    double angle = 0.0;   // general: how it is shown (region_symmetry.h)
    bool mirror = false;
    bool general() const { return !region.is_empty(); }
  };
  // A grid part as the training caches key it: its state (the lookahead's rewards and the scale
  // features) and value depend on its face's size too, and parts of different faces can share cells.
  struct GridKey {
    Part part;
    double face_size = 1.0;
    bool operator==(const GridKey& other) const { return face_size == other.face_size && part == other.part; }
  };
  struct GridKeyHash {
    size_t operator()(const GridKey& key) const {
      return key.part.hash() ^ (std::hash<double>()(key.face_size) * 0x9e3779b97f4a7c15ULL);
    }
  };
  // A general part as the caches key it: states and values depend on the face's size and rules too.
  struct RegionKey {
    Region region;
    double face_size = 1.0;
    BlockRules rules;
    bool operator==(const RegionKey& other) const;
  };
  struct RegionKeyHash {
    size_t operator()(const RegionKey& key) const;
  };
  void push_memory(Memory entry);  // the ring buffer's insertion
  std::shared_ptr<const RegionPartState> cached_region_state(const Region& region, double face_size, const BlockRules& rules);
  torch::Tensor forward_values(ValueNetwork& network, const std::vector<const PartState*>& states);
  std::vector<double> values_of(ValueNetwork& network, const std::vector<const PartState*>& states);
  std::shared_ptr<const PartState> cached_state(const Part& part, double face_size);

  SacConfig config_;
  double scale_;
  bool deploy_reuse_ = true;
  bool averaging() const { return config_.weight_average_decay > 0.0; }
  void update_average();

  ValueNetwork value_{nullptr}, target_{nullptr}, average_{nullptr};  // average_: only when averaging()
  std::unique_ptr<CutProposer> proposer_;  // only with actor_candidates > 0
  torch::Tensor log_alpha_;
  std::unique_ptr<torch::optim::Adam> value_optimizer_, temperature_optimizer_;
  std::vector<Memory> memory_;
  size_t next_ = 0;
  long steps_ = 0, updates_ = 0;
  std::unordered_map<GridKey, std::shared_ptr<const PartState>, GridKeyHash> states_;
  std::unordered_map<GridKey, double, GridKeyHash> target_values_;  // W' of parts, valid until the next refresh
  std::unordered_map<RegionKey, std::shared_ptr<const RegionPartState>, RegionKeyHash> region_states_;
  std::unordered_map<RegionKey, double, RegionKeyHash> region_target_values_;  // W' of general parts
};

}  // namespace autoblock
