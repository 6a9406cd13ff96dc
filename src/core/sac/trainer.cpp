#include "core/sac/trainer.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "core/common/error.h"
#include "core/env/decomposition.h"
#include "core/sac/part_state.h"
#include "core/sac/policy_file.h"
#include "core/sac/sac_policy.h"

namespace autoblock {

nlohmann::json episode_record_json(const EpisodeRecord& r) {
  nlohmann::json j = {{"episode", r.episode}, {"shape", r.shape},   {"return", r.ret},
                      {"blocks", r.blocks},   {"steps", r.steps},   {"complete", r.complete},
                      {"metrics", r.metrics}, {"alpha", r.alpha},   {"tau", r.tau},
                      {"evaluated", r.evaluated}, {"test_return", r.test_return}, {"wall_seconds", r.wall_seconds}};
  return j;
}

EpisodeRecord episode_record_from_json(const nlohmann::json& j) {
  EpisodeRecord r;
  r.episode = j.at("episode").get<int>();
  r.shape = j.at("shape").get<std::string>();
  r.ret = j.at("return").get<double>();
  r.blocks = j.at("blocks").get<int>();
  r.steps = j.at("steps").get<int>();
  r.complete = j.at("complete").get<bool>();
  r.metrics = j.at("metrics").get<std::map<std::string, double>>();
  r.alpha = j.at("alpha").get<double>();
  r.tau = j.at("tau").get<double>();
  r.evaluated = j.at("evaluated").get<bool>();
  r.test_return = j.at("test_return").get<double>();
  r.wall_seconds = j.at("wall_seconds").get<double>();
  return r;
}

Trainer::Trainer(const TrainerOptions& options, TrainingSet train, TrainingSet test)
    : options_(options), train_(std::move(train)), test_(std::move(test)), rng_(options.seed) {
  if (train_.faces.empty()) throw InputError("the training set holds no face");
  if (test_.faces.empty()) throw InputError("the test set holds no face");
  if (options_.episodes < 1) throw InputError("train at least one episode");
  torch::set_num_threads(std::max(1, options_.threads));
}

Trainer::Trainer(const SacConfig& config, const TrainerOptions& options, TrainingSet train, TrainingSet test)
    : Trainer(options, std::move(train), std::move(test)) {
  torch::manual_seed(options.seed);
  agent_ = std::make_shared<SacAgent>(config);
  buffer_ = std::make_unique<ReplayBuffer>(static_cast<size_t>(config.buffer_capacity));
}

Trainer Trainer::resume(const std::string& checkpoint, const TrainerOptions& options, TrainingSet train, TrainingSet test) {
  LoadedPolicy loaded = load_policy_file(checkpoint, true);
  Trainer trainer(options, std::move(train), std::move(test));
  trainer.agent_ = loaded.agent;
  trainer.buffer_ = std::move(loaded.buffer);
  try {
    const nlohmann::json& t = loaded.meta.at("training");
    std::istringstream rng_state(t.at("rng").get<std::string>());
    rng_state >> trainer.rng_;
    trainer.total_steps_ = t.at("total_steps").get<long>();
    trainer.episodes_done_ = t.at("episodes_done").get<int>();
    trainer.elapsed_before_ = t.at("elapsed_seconds").get<double>();
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
                                   {"total_steps", total_steps_},
                                   {"episodes_done", episodes_done_},
                                   {"elapsed_seconds", history_.empty() ? 0.0 : history_.back().wall_seconds},
                                   {"seed", options_.seed},
                                   {"history", history}};
  save_policy_file(path, *agent_, training, buffer_.get());
}

double Trainer::evaluate_test() {
  SacPolicy policy(agent_, "sac");
  EpisodeOptions options;
  options.reward = agent_->config().reward;
  options.max_steps = options_.max_steps;
  double total = 0.0;
  for (const GridFace& face : test_.faces) total += decompose_face(face, policy, options).total_return;
  return total / static_cast<double>(test_.faces.size());
}

EpisodeRecord Trainer::run_episode() {
  const SacConfig& config = agent_->config();
  const size_t index = std::uniform_int_distribution<size_t>(0, train_.faces.size() - 1)(rng_);
  EpisodeOptions episode_options;
  episode_options.reward = config.reward;
  episode_options.max_steps = options_.max_steps;
  Episode episode(train_.faces[index], episode_options);
  std::map<int, std::shared_ptr<const PartState>> states;
  std::map<std::string, double> metric_sums;
  int updates = 0;
  while (episode.running()) {
    const int id = episode.current_part_id();
    auto& state = states[id];
    if (!state) state = make_part_state(episode.current_part(), config.graph);
    const int vertex_count = static_cast<int>(state->observations.size());
    Action action;
    if (total_steps_ < config.warmup_steps) {
      action.vertex = std::uniform_int_distribution<int>(0, vertex_count - 1)(rng_);
      action.direction = static_cast<CutDirection>(std::uniform_int_distribution<int>(0, 1)(rng_));
    } else {
      const std::vector<float> values = agent_->vertex_values(*state);
      const double tau = agent_->vertex_temperature();
      const double top = *std::max_element(values.begin(), values.end());
      std::vector<double> weights;
      for (float v : values) weights.push_back(std::exp((static_cast<double>(v) - top) / tau));
      action.vertex = std::discrete_distribution<int>(weights.begin(), weights.end())(rng_);
      const auto p = agent_->direction_probabilities(state->observations[static_cast<size_t>(action.vertex)]);
      action.direction = std::bernoulli_distribution(static_cast<double>(p[1]))(rng_) ? CutDirection::Vertical
                                                                                      : CutDirection::Horizontal;
    }
    const CutRecord& cut = episode.step(action);
    Transition transition;
    transition.state = state;
    transition.vertex = action.vertex;
    transition.direction = static_cast<int>(action.direction);
    transition.reward = static_cast<float>(cut.reward);
    for (int child : cut.children) {
      for (const Piece& piece : episode.queue()) {
        if (piece.id != child) continue;
        auto& child_state = states[child];
        if (!child_state) child_state = make_part_state(piece.part, config.graph);
        transition.children.push_back(child_state);
      }
    }
    buffer_->add(std::move(transition));
    ++total_steps_;
    if (total_steps_ > config.warmup_steps && buffer_->size() >= static_cast<size_t>(config.batch_size) &&
        total_steps_ % config.update_every == 0) {
      for (const auto& [name, value] : agent_->update(buffer_->sample(static_cast<size_t>(config.batch_size), rng_))) {
        metric_sums[name] += value;
      }
      ++updates;
    }
  }
  EpisodeRecord record;
  record.shape = train_.names.empty() ? std::to_string(index) : train_.names[index];
  record.ret = episode.total_return();
  record.blocks = static_cast<int>(episode.blocks().size());
  record.steps = episode.steps();
  record.complete = episode.status() == EpisodeStatus::Complete;
  for (const auto& [name, sum] : metric_sums) record.metrics[name] = sum / updates;
  record.alpha = agent_->direction_temperature();
  record.tau = agent_->vertex_temperature();
  return record;
}

void Trainer::run(const std::function<void(const EpisodeRecord&)>& on_episode, const std::function<bool()>& should_stop) {
  const auto start = std::chrono::steady_clock::now();
  const double before = history_.empty() ? 0.0 : history_.back().wall_seconds;
  while (episodes_done_ < options_.episodes) {
    if (should_stop && should_stop()) break;
    EpisodeRecord record = run_episode();
    record.episode = ++episodes_done_;
    if (episodes_done_ % options_.eval_every == 0 || episodes_done_ == options_.episodes) {
      record.evaluated = true;
      record.test_return = evaluate_test();
    }
    record.wall_seconds = before + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    history_.push_back(record);
    if (on_episode) on_episode(record);
    if (!options_.checkpoint_path.empty() &&
        (episodes_done_ % options_.checkpoint_every == 0 || episodes_done_ == options_.episodes)) {
      save_checkpoint(options_.checkpoint_path);
    }
  }
  if (!options_.checkpoint_path.empty() && episodes_done_ < options_.episodes) save_checkpoint(options_.checkpoint_path);
}

}  // namespace autoblock
