#include "core/sac/trainer.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include <torch/torch.h>

#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/region/region_policy.h"
#include "core/nn/threads.h"
#include "core/sac/policy_file.h"

namespace autoblock {

Trainer::Trainer(const TrainerOptions& options, TrainingSet train, TrainingSet test)
    : options_(options), train_(std::move(train)), test_(std::move(test)), rng_(options.seed) {
  if (train_.size() == 0) throw InputError("the training set holds no face");
  if (test_.size() == 0) throw InputError("the test set holds no face");
  if (options_.episodes < 1) throw InputError("train at least one episode");
  // LibTorch's threads do the work; OpenBLAS's own pool would compete with them (nn/threads.h).
  torch::set_num_threads(std::max(1, options_.threads));
  set_blas_threads(1);
}

Trainer::Trainer(const SacConfig& config, const TrainerOptions& options, TrainingSet train, TrainingSet test)
    : Trainer(options, std::move(train), std::move(test)) {
  torch::manual_seed(options.seed);
  agent_ = make_learning_agent(config);
  require_general_agent();
}

void Trainer::require_general_agent() const {
  if ((!train_.general.empty() || !test_.general.empty()) && !agent_->deployed_region_policy("")) {
    throw InputError("this " + agent_->config().agent + " agent learns on faces whose edges run along two perpendicular "
                     "directions only (its checkpoint was written before the paper's agent learned on general faces), "
                     "and the data holds faces with edges at other angles: start a fresh run");
  }
}

Trainer Trainer::resume(const std::string& checkpoint, const TrainerOptions& options, TrainingSet train, TrainingSet test) {
  LoadedPolicy loaded = load_policy_file(checkpoint, true);
  Trainer trainer(options, std::move(train), std::move(test));
  trainer.agent_ = loaded.agent;
  trainer.require_general_agent();
  try {
    const nlohmann::json& t = loaded.meta.at("training");
    std::istringstream rng_state(t.at("rng").get<std::string>());
    rng_state >> trainer.rng_;
    trainer.episodes_done_ = t.at("episodes_done").get<int>();
    for (const auto& record : t.at("history")) trainer.history_.push_back(episode_record_from_json(record));
  } catch (const nlohmann::json::exception&) {
    throw InputError(checkpoint + ": the checkpoint's training state is malformed");
  }
  return trainer;
}

void Trainer::save_checkpoint(const std::string& path) const {
  std::ostringstream rng_state;
  rng_state << rng_;
  nlohmann::json history = nlohmann::json::array();
  for (const EpisodeRecord& r : history_) history.push_back(episode_record_json(r));
  const nlohmann::json training = {{"rng", rng_state.str()},
                                   {"episodes_done", episodes_done_},
                                   {"elapsed_seconds", history_.empty() ? 0.0 : history_.back().wall_seconds},
                                   {"seed", options_.seed},
                                   {"history", history}};
  save_policy_file(path, *agent_, training, true);
}

double Trainer::evaluate_test() {
  std::unique_ptr<Policy> policy = agent_->deployed_policy("sac");
  EpisodeOptions options;
  options.reward = agent_->config().reward;
  options.max_steps = options_.max_steps;
  double total = 0.0;
  for (const GridFace& face : test_.faces) total += decompose_face(face, *policy, options).total_return;
  if (!test_.general.empty()) {
    std::unique_ptr<RegionPolicy> general = agent_->deployed_region_policy("sac");
    RegionEpisodeOptions region_options;
    region_options.reward = agent_->config().reward;
    region_options.max_steps = options_.max_steps;
    const auto lock = lock_general_engine();
    for (const Region& face : test_.general) total += decompose_region(face, *general, region_options).total_return;
  }
  return total / static_cast<double>(test_.size());
}

void Trainer::run(const std::function<void(const EpisodeRecord&)>& on_episode, const std::function<bool()>& should_stop) {
  const auto start = std::chrono::steady_clock::now();
  const double before = history_.empty() ? 0.0 : history_.back().wall_seconds;
  while (episodes_done_ < options_.episodes) {
    if (should_stop && should_stop()) break;
    const size_t index = std::uniform_int_distribution<size_t>(0, train_.size() - 1)(rng_);
    agent_->set_training_progress(static_cast<double>(episodes_done_) / static_cast<double>(options_.episodes));
    EpisodeRecord record;
    if (index < train_.faces.size()) {
      record = agent_->train_episode(train_.faces[index], rng_, options_.max_steps);
      record.shape = train_.names.empty() ? std::to_string(index) : train_.names[index];
    } else {
      const size_t g = index - train_.faces.size();
      record = agent_->train_region_episode(train_.general[g], rng_, options_.max_steps);
      record.shape = train_.general_names.empty() ? "general " + std::to_string(g) : train_.general_names[g];
    }
    record.episode = ++episodes_done_;
    if (episodes_done_ % options_.eval_every == 0 || episodes_done_ == options_.episodes) {
      record.evaluated = true;
      record.test_return = evaluate_test();
    }
    record.wall_seconds = before + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    history_.push_back(record);
    if (on_episode) on_episode(record);
    // At every checkpoint's place, written or not, so that a run and the same run resumed from a
    // checkpoint hold the same state from there on.
    if ((options_.checkpoint_every > 0 && episodes_done_ % options_.checkpoint_every == 0) ||
        episodes_done_ == options_.episodes) {
      agent_->prepare_checkpoint();
      if (!options_.checkpoint_path.empty()) save_checkpoint(options_.checkpoint_path);
    }
  }
  if (!options_.checkpoint_path.empty() && episodes_done_ < options_.episodes) {
    agent_->prepare_checkpoint();
    save_checkpoint(options_.checkpoint_path);
  }
}

}  // namespace autoblock
