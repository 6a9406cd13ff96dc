#include "core/sac/paper_agent.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/sac/part_state.h"
#include "core/sac/sac_policy.h"

namespace autoblock {

PaperAgent::PaperAgent(const SacConfig& config)
    : agent_(std::make_shared<SacAgent>(config)), buffer_(static_cast<size_t>(config.buffer_capacity)) {}

std::unique_ptr<Policy> PaperAgent::deployed_policy(const std::string& name) {
  return std::make_unique<SacPolicy>(agent_, name);
}

std::vector<float> PaperAgent::vertex_scores(const Episode& episode) {
  return agent_->vertex_values(*make_part_state(episode.current_part(), agent_->config().graph));
}

EpisodeRecord PaperAgent::train_episode(const GridFace& face, std::mt19937_64& rng, int max_steps) {
  const SacConfig& config = agent_->config();
  EpisodeOptions options;
  options.reward = config.reward;
  options.max_steps = max_steps;
  Episode episode(face, options);
  std::map<int, std::shared_ptr<const PartState>> states;
  std::map<std::string, double> metric_sums;
  int updates = 0;
  while (episode.running()) {
    const int id = episode.current_part_id();
    auto& state = states[id];
    if (!state) state = make_part_state(episode.current_part(), config.graph);
    const int vertex_count = static_cast<int>(state->observations.size());
    Action action;
    if (steps_ < config.warmup_steps) {
      action.vertex = std::uniform_int_distribution<int>(0, vertex_count - 1)(rng);
      action.direction = static_cast<CutDirection>(std::uniform_int_distribution<int>(0, 1)(rng));
    } else {
      const std::vector<float> values = agent_->vertex_values(*state);
      const double tau = agent_->vertex_temperature();
      const double top = *std::max_element(values.begin(), values.end());
      std::vector<double> weights;
      for (float v : values) weights.push_back(std::exp((static_cast<double>(v) - top) / tau));
      action.vertex = std::discrete_distribution<int>(weights.begin(), weights.end())(rng);
      const auto p = agent_->direction_probabilities(state->observations[static_cast<size_t>(action.vertex)]);
      action.direction = std::bernoulli_distribution(static_cast<double>(p[1]))(rng) ? CutDirection::Vertical
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
    buffer_.add(std::move(transition));
    ++steps_;
    if (steps_ > config.warmup_steps && buffer_.size() >= static_cast<size_t>(config.batch_size) &&
        steps_ % config.update_every == 0) {
      for (const auto& [name, value] : agent_->update(buffer_.sample(static_cast<size_t>(config.batch_size), rng))) {
        metric_sums[name] += value;
      }
      ++updates;
    }
  }
  EpisodeRecord record = episode_record_of(episode, metric_sums, updates);
  record.alpha = agent_->direction_temperature();
  record.tau = agent_->vertex_temperature();
  return record;
}

void PaperAgent::save(torch::serialize::OutputArchive& archive, bool training) const {
  agent_->save(archive, training);
  if (training) archive.write("steps", torch::full({}, static_cast<int64_t>(steps_), torch::kInt64));
}

void PaperAgent::load(torch::serialize::InputArchive& archive, bool training) {
  agent_->load(archive, training);
  if (training) {
    torch::Tensor steps;
    archive.read("steps", steps);
    steps_ = steps.item<int64_t>();
  }
}

}  // namespace autoblock
