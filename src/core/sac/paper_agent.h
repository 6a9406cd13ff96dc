// The paper's agent as a LearningAgent: SacAgent (sac_agent.h) with its replay buffer. Training
// acts as the paper says: a vertex drawn from softmax(values / tau) at the part's model vertices,
// a direction drawn from the actor, every cut (also those that change nothing) remembered, one
// SAC update per cut after the warm-up (warm-up cuts are uniform over vertices and directions).
#pragma once

#include <memory>

#include "core/sac/learning_agent.h"
#include "core/sac/replay_buffer.h"
#include "core/sac/sac_agent.h"

namespace autoblock {

class PaperAgent : public LearningAgent {
 public:
  explicit PaperAgent(const SacConfig& config);
  const SacConfig& config() const override { return agent_->config(); }
  EpisodeRecord train_episode(const GridFace& face, std::mt19937_64& rng, int max_steps) override;
  std::unique_ptr<Policy> deployed_policy(const std::string& name) override;
  std::vector<float> vertex_scores(const Episode& episode) override;
  void save(torch::serialize::OutputArchive& archive, bool training) const override;
  void load(torch::serialize::InputArchive& archive, bool training) override;
  std::string serialize_memory() const override { return buffer_.serialize(); }
  void deserialize_memory(const std::string& bytes) override { buffer_ = ReplayBuffer::deserialize(bytes); }

  SacAgent& sac() { return *agent_; }

 private:
  std::shared_ptr<SacAgent> agent_;
  ReplayBuffer buffer_;
  long steps_ = 0;
};

}  // namespace autoblock
