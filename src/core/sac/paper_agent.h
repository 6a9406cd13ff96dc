// The paper's agent as a LearningAgent: SacAgent (sac_agent.h) with its replay buffer. Training
// acts as the paper says: a vertex drawn from softmax(values / tau) at the part's model vertices,
// a direction drawn from the actor, every cut (also those that change nothing) remembered, one
// SAC update per cut after the warm-up (warm-up cuts are uniform over vertices and directions).
//
// On general faces (issue 12) the cut's angle is continuous: ContinuousSacAgent
// (continuous_sac_agent.h) with its own networks and replay buffer, trained the same way (warm-up
// cuts uniform over the vertices, the template where it applies, and u in [-1, 1]). Its networks
// are stored under "general_" keys; a policy file written before it has none, and its agent has no
// policy on general faces (deployed_region_policy returns nullptr; the trainer refuses general data).
#pragma once

#include <memory>

#include "core/sac/learning_agent.h"
#include "core/sac/replay_buffer.h"
#include "core/sac/continuous_sac_agent.h"
#include "core/sac/sac_agent.h"

namespace autoblock {

class PaperAgent : public LearningAgent {
 public:
  explicit PaperAgent(const SacConfig& config);
  const SacConfig& config() const override { return agent_->config(); }
  EpisodeRecord train_episode(const GridFace& face, std::mt19937_64& rng, int max_steps) override;
  EpisodeRecord train_region_episode(const Region& face, std::mt19937_64& rng, int max_steps) override;
  std::unique_ptr<Policy> deployed_policy(const std::string& name) override;
  std::unique_ptr<RegionPolicy> deployed_region_policy(const std::string& name) override;
  std::vector<float> vertex_scores(const Episode& episode) override;
  std::vector<float> region_vertex_scores(const RegionEpisode& episode) override;
  // A warm start from a policy written before the continuous agent keeps this agent's own (fresh)
  // networks for general faces.
  void copy_weights_from(const LearningAgent& other) override;
  void save(torch::serialize::OutputArchive& archive, bool training) const override;
  void load(torch::serialize::InputArchive& archive, bool training) override;
  std::string serialize_memory() const override;
  void deserialize_memory(const std::string& bytes) override;

  SacAgent& sac() { return *agent_; }
  ContinuousSacAgent& general() { return *general_; }
  // False for an agent loaded from a file written before the continuous agent.
  bool has_general() const { return has_general_; }

 private:
  std::shared_ptr<SacAgent> agent_;
  std::shared_ptr<ContinuousSacAgent> general_;
  bool has_general_ = true;
  ReplayBuffer buffer_, general_buffer_;
  long steps_ = 0, general_steps_ = 0;
};


}  // namespace autoblock
