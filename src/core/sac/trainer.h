// The paper's training loop: one face from the training set per episode (rectilinear or, for the
// lookahead agent, general: TrainingSet holds both, drawn uniformly over all of them), cuts chosen
// stochastically by the agent, which learns as it goes (learning_agent.h), periodic deterministic
// evaluation on the test set, checkpoints that let a killed run resume where it stopped.
//
// Reproducibility: every random choice (shape, vertex, direction, replay batch) comes from one
// seeded generator, the networks' initial weights from torch::manual_seed(seed); with one thread a
// seeded run, and a run resumed from any of its checkpoints, repeat exactly.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/geometry/grid_face.h"
#include "core/io/dataset.h"
#include "core/sac/episode_record.h"
#include "core/sac/learning_agent.h"

namespace autoblock {

struct TrainerOptions {
  int episodes = 1500;           // total, counting episodes before a resume
  std::uint64_t seed = 0;
  int eval_every = 25;           // episodes between evaluations on the test set
  int checkpoint_every = 25;     // episodes between checkpoints
  std::string checkpoint_path;   // empty: no checkpoints
  int threads = 1;               // LibTorch intra-op threads
  int max_steps = 0;             // step cap per episode (0: the environment's default)
};

class Trainer {
 public:
  // A fresh run. Throws InputError when a set is empty.
  Trainer(const SacConfig& config, const TrainerOptions& options, TrainingSet train, TrainingSet test);
  // Continue the run saved in checkpoint (its configuration, networks, replay buffer, generator
  // state and history); options.episodes is the new total.
  static Trainer resume(const std::string& checkpoint, const TrainerOptions& options, TrainingSet train, TrainingSet test);

  // Runs episodes until options.episodes are done or should_stop() says so (asked between
  // episodes; a checkpoint is written before returning when checkpoint_path is set).
  void run(const std::function<void(const EpisodeRecord&)>& on_episode, const std::function<bool()>& should_stop = {});

  // Mean deterministic return of the current agent over the test set.
  double evaluate_test();
  void save_checkpoint(const std::string& path) const;

  int episodes_done() const { return episodes_done_; }
  const std::vector<EpisodeRecord>& history() const { return history_; }
  std::shared_ptr<LearningAgent> agent() const { return agent_; }
  const TrainerOptions& options() const { return options_; }
  const TrainingSet& test_set() const { return test_; }

 private:
  Trainer(const TrainerOptions& options, TrainingSet train, TrainingSet test);
  // Throws InputError when the data holds general faces and the agent does not learn on them.
  void require_general_agent() const;
  TrainerOptions options_;
  TrainingSet train_, test_;
  std::shared_ptr<LearningAgent> agent_;
  std::mt19937_64 rng_;
  int episodes_done_ = 0;
  std::vector<EpisodeRecord> history_;
};

}  // namespace autoblock
