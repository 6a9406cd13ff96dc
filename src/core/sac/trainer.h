// The paper's training loop: one face from the training set per episode, cuts chosen
// stochastically by the agent, one SAC update per cut after a warm-up, periodic deterministic
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
#include "core/sac/replay_buffer.h"
#include "core/sac/sac_agent.h"

namespace autoblock {

struct TrainingSet {
  std::vector<GridFace> faces;
  std::vector<std::string> names;
};

struct TrainerOptions {
  int episodes = 1500;           // total, counting episodes before a resume
  std::uint64_t seed = 0;
  int eval_every = 25;           // episodes between evaluations on the test set
  int checkpoint_every = 25;     // episodes between checkpoints
  std::string checkpoint_path;   // empty: no checkpoints
  int threads = 1;               // LibTorch intra-op threads
  int max_steps = 0;             // step cap per episode (0: the environment's default)
};

struct EpisodeRecord {
  int episode = 0;               // 1-based
  std::string shape;
  double ret = 0.0;              // the episode's return (plain sum of the rewards)
  int blocks = 0;
  int steps = 0;
  bool complete = false;
  std::map<std::string, double> metrics;  // means over the episode's updates (empty during warm-up)
  double alpha = 0.0, tau = 0.0;
  bool evaluated = false;
  double test_return = 0.0;      // mean deterministic return over the test set, when evaluated
  double wall_seconds = 0.0;     // since training started (a resumed run continues the clock)
};

nlohmann::json episode_record_json(const EpisodeRecord& record);
EpisodeRecord episode_record_from_json(const nlohmann::json& json);

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
  std::shared_ptr<SacAgent> agent() const { return agent_; }
  const TrainerOptions& options() const { return options_; }

 private:
  Trainer(const TrainerOptions& options, TrainingSet train, TrainingSet test);
  EpisodeRecord run_episode();

  TrainerOptions options_;
  TrainingSet train_, test_;
  std::shared_ptr<SacAgent> agent_;
  std::unique_ptr<ReplayBuffer> buffer_;
  std::mt19937_64 rng_;
  long total_steps_ = 0;
  int episodes_done_ = 0;
  double elapsed_before_ = 0.0;  // seconds spent before this process's run (resumes)
  std::vector<EpisodeRecord> history_;
};

}  // namespace autoblock
