// A trainable decomposition agent, as the trainer and the policy files see it. Two exist:
//   "paper"     the paper's SAC agent, faithfully (paper_agent.h, sac_agent.h);
//   "lookahead" SAC-style maximum-entropy learning with a one-cut lookahead (lookahead_agent.h).
#pragma once

#include <memory>
#include <random>
#include <string>
#include <vector>

#include <torch/serialize/archive.h>

#include "core/env/episode.h"
#include "core/env/policy.h"
#include "core/geometry/grid_face.h"
#include "core/region/region.h"
#include "core/sac/episode_record.h"
#include "core/sac/sac_config.h"

namespace autoblock {

class RegionEpisode;
class RegionPolicy;

// Agents live in shared pointers (make_learning_agent): their deployed policies share them.
class LearningAgent : public std::enable_shared_from_this<LearningAgent> {
 public:
  virtual ~LearningAgent() = default;
  virtual const SacConfig& config() const = 0;

  // One training episode on face: act stochastically (uniformly during the warm-up), remember,
  // learn. Output: the episode's record (no episode number, evaluation or clock yet).
  virtual EpisodeRecord train_episode(const GridFace& face, std::mt19937_64& rng, int max_steps) = 0;
  // The same on a general face (issue 12; face, a region, not empty), under the agent's reward
  // preset and the face's block rules (region_episode.h). The default throws InputError: the agent
  // learns on rectilinear faces only.
  virtual EpisodeRecord train_region_episode(const Region& face, std::mt19937_64& rng, int max_steps);
  // Where the run stands, told before every training episode: episodes done over the run's total,
  // in [0, 1]. Agents with a learning-rate schedule follow it; the default ignores it.
  virtual void set_training_progress(double fraction) { (void)fraction; }
  // Called before a checkpoint is written: drops what the agent keeps that a resumed run cannot have
  // (values computed in batches that a resumed run composes differently: a batch's forward pass rounds
  // a graph's value differently from another's), so that a resumed run repeats the run exactly.
  virtual void prepare_checkpoint() {}

  // The deterministic deployed policy, sharing this agent (which it does not change).
  virtual std::unique_ptr<Policy> deployed_policy(const std::string& name) = 0;
  // The deterministic deployed policy on general faces; nullptr when the agent has none.
  virtual std::unique_ptr<RegionPolicy> deployed_region_policy(const std::string& name);
  // The value network's score at every model vertex of the episode's current part.
  virtual std::vector<float> vertex_scores(const Episode& episode) = 0;
  // The same on a general face's episode (the deployed region policy's shortlist; the caller holds
  // lock_general_engine()). The default throws InputError: the agent has no policy on general faces.
  virtual std::vector<float> region_vertex_scores(const RegionEpisode& episode);

  // Inputs: archive; training, true for a checkpoint (target networks, optimisers, counters).
  virtual void save(torch::serialize::OutputArchive& archive, bool training) const = 0;
  virtual void load(torch::serialize::InputArchive& archive, bool training) = 0;
  // Takes other's deployed networks (and temperature) as this agent's starting weights, targets
  // included: a warm start. Throws InputError when the two are of different kinds or networks.
  virtual void copy_weights_from(const LearningAgent& other);

  // The replay memory as bytes, and back (throws InputError for malformed bytes).
  virtual std::string serialize_memory() const = 0;
  virtual void deserialize_memory(const std::string& bytes) = 0;
};

// Inputs: config (config.agent names the kind). Output: a fresh agent; the caller seeds torch.
// Throws InputError for an unknown kind.
std::shared_ptr<LearningAgent> make_learning_agent(const SacConfig& config);

}  // namespace autoblock
