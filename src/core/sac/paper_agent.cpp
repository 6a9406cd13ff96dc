#include "core/sac/paper_agent.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>

#include "core/common/error.h"
#include "core/region/block.h"
#include "core/region/region_candidates.h"
#include "core/region/region_episode.h"
#include "core/region/region_policy.h"
#include "core/region/region_reward.h"
#include "core/sac/continuous_region_policy.h"
#include "core/sac/part_state.h"
#include "core/sac/region_state.h"
#include "core/sac/sac_policy.h"
#include "core/sac/softmax_draw.h"

namespace autoblock {
namespace {

constexpr char kMemoryMagic[4] = {'A', 'B', 'P', 'M'};  // both replay buffers; a lone buffer is the old form

}  // namespace

PaperAgent::PaperAgent(const SacConfig& config)
    : agent_(std::make_shared<SacAgent>(config)),
      general_(std::make_shared<ContinuousSacAgent>(config)),
      buffer_(static_cast<size_t>(config.buffer_capacity)),
      general_buffer_(static_cast<size_t>(config.buffer_capacity)) {}

std::unique_ptr<Policy> PaperAgent::deployed_policy(const std::string& name) {
  return std::make_unique<SacPolicy>(agent_, name);
}

std::unique_ptr<RegionPolicy> PaperAgent::deployed_region_policy(const std::string& name) {
  if (!has_general_) return nullptr;
  return std::make_unique<ContinuousRegionPolicy>(general_, agent_->config(), name);
}

std::vector<float> PaperAgent::vertex_scores(const Episode& episode) {
  return agent_->vertex_values(*make_part_state(episode.current_part(), agent_->config().graph));
}

std::vector<float> PaperAgent::region_vertex_scores(const RegionEpisode& episode) {
  if (!has_general_) return LearningAgent::region_vertex_scores(episode);
  return ContinuousRegionPolicy(general_, agent_->config(), "").vertex_scores(episode);
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
      action.vertex = static_cast<int>(
          sample_softmax(std::vector<double>(values.begin(), values.end()), agent_->vertex_temperature(), rng));
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

EpisodeRecord PaperAgent::train_region_episode(const Region& face, std::mt19937_64& rng, int max_steps) {
  if (!has_general_) return LearningAgent::train_region_episode(face, rng, max_steps);
  const SacConfig& config = agent_->config();
  const auto lock = lock_general_engine();
  RegionEpisodeOptions options;
  options.reward = config.reward;
  options.max_steps = max_steps;
  RegionEpisode episode(face, options);
  const double face_size = episode.face_size();
  const BlockRules rules = episode.options().rules;
  struct Known {
    std::shared_ptr<const PartState> state;
    float template_reward = kNoTemplateReward;
  };
  std::map<int, Known> parts;  // by part id
  auto known = [&](int id, const Region& part) -> const Known& {
    Known& k = parts[id];
    if (!k.state) {
      k.state = general_state(part, config.graph);
      k.template_reward = template_choice_reward(part, config.reward, face_size, rules);
    }
    return k;
  };
  std::map<std::string, double> metric_sums;
  int updates = 0;
  // Remembers a transition and learns (one update per update_every steps after the warm-up).
  auto remember = [&](Transition transition) {
    general_buffer_.add(std::move(transition));
    ++general_steps_;
    if (general_steps_ > config.warmup_steps && general_buffer_.size() >= static_cast<size_t>(config.batch_size) &&
        general_steps_ % config.update_every == 0) {
      const auto batch = general_buffer_.sample(static_cast<size_t>(config.batch_size), rng);
      for (const auto& [name, value] : general_->update(batch, rng)) metric_sums[name] += value;
      ++updates;
    }
  };
  constexpr int kMaskedDraws = 8;  // region_mask: draws per step before the progress cut
  while (episode.running()) {
    const int id = episode.current_part_id();
    const Region part = episode.current_part();
    const Known& k = known(id, part);
    const size_t vertices = k.state->observations.size();
    const size_t choices = vertices + (std::isnan(k.template_reward) ? 0 : 1);
    for (int draw = 1;; ++draw) {
      size_t choice;
      double u;
      if (general_steps_ < config.warmup_steps) {
        choice = std::uniform_int_distribution<size_t>(0, choices - 1)(rng);
        u = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
      } else {
        const std::vector<float> values = general_->vertex_values(*k.state);
        std::vector<double> q(values.begin(), values.end());
        if (choices > vertices) q.push_back(k.template_reward);
        choice = sample_softmax(q, general_->vertex_temperature(), rng);
        u = choice < vertices ? general_->angle_action(k.state->observations[choice], &rng) : 0.0;
      }
      if (choice == vertices) {  // the template: its value is its reward, nothing to learn
        RegionAction action;
        action.kind = RegionAction::Kind::Template;
        episode.step(action);
        break;
      }
      RegionAction action;
      action.cut = cut_of_angle(part, static_cast<int>(choice), u);
      Transition transition;
      transition.state = k.state;
      transition.vertex = static_cast<int>(choice);
      transition.angle = static_cast<float>(u);
      CutOutcome outcome = episode.outcome_of(action);
      if (config.region_mask && !makes_progress(part, outcome.pieces, rules)) {
        // Remembered with its reward and what it would leave, not made.
        transition.reward = static_cast<float>(episode.reward_of(action, outcome));
        if (outcome.pieces.size() < 2) {
          transition.children.push_back(k.state);
          transition.children_template.push_back(k.template_reward);
        } else {
          for (const Region& piece : outcome.pieces) {
            if (block_corners(piece, rules)) continue;
            transition.children.push_back(general_state(piece, config.graph));
            transition.children_template.push_back(template_choice_reward(piece, config.reward, face_size, rules));
          }
        }
        remember(std::move(transition));
        if (draw < kMaskedDraws) continue;
        episode.step(progress_action(part, rules));  // as deployed: not the actor's, nothing to learn
        break;
      }
      const RegionCutRecord& cut = episode.step(action, std::move(outcome));
      transition.reward = static_cast<float>(cut.reward);
      for (const int child : cut.children) {
        for (const RegionPiece& piece : episode.queue()) {
          if (piece.id != child) continue;
          const Known& c = known(child, piece.region);
          transition.children.push_back(c.state);
          transition.children_template.push_back(c.template_reward);
        }
      }
      remember(std::move(transition));
      break;
    }
  }
  EpisodeRecord record = region_episode_record_of(episode, metric_sums, updates);
  record.alpha = general_->angle_temperature();
  record.tau = general_->vertex_temperature();
  return record;
}

void PaperAgent::copy_weights_from(const LearningAgent& other) {
  LearningAgent::copy_weights_from(other);
  has_general_ = true;  // the general networks stay as they were when other has none
}

void PaperAgent::save(torch::serialize::OutputArchive& archive, bool training) const {
  agent_->save(archive, training);
  if (has_general_) general_->save(archive, "general_", training);
  if (!training) return;
  archive.write("steps", torch::full({}, static_cast<int64_t>(steps_), torch::kInt64));
  if (has_general_) archive.write("general_steps", torch::full({}, static_cast<int64_t>(general_steps_), torch::kInt64));
}

void PaperAgent::load(torch::serialize::InputArchive& archive, bool training) {
  agent_->load(archive, training);
  torch::serialize::InputArchive probe;
  has_general_ = archive.try_read("general_value", probe);  // files before the continuous agent have none
  if (has_general_) general_->load(archive, "general_", training);
  if (training) {
    torch::Tensor steps;
    archive.read("steps", steps);
    steps_ = steps.item<int64_t>();
    if (has_general_) {
      archive.read("general_steps", steps);
      general_steps_ = steps.item<int64_t>();
    }
  }
}

std::string PaperAgent::serialize_memory() const {
  const std::string grid = buffer_.serialize(), general = general_buffer_.serialize();
  std::string bytes(kMemoryMagic, 4);
  const std::uint64_t size = grid.size();
  bytes.append(reinterpret_cast<const char*>(&size), sizeof size);
  return bytes + grid + general;
}

void PaperAgent::deserialize_memory(const std::string& bytes) {
  if (bytes.size() < 4 || std::memcmp(bytes.data(), kMemoryMagic, 4) != 0) {
    buffer_ = ReplayBuffer::deserialize(bytes);  // a checkpoint written before the continuous agent
    return;
  }
  std::uint64_t size = 0;
  if (bytes.size() < 4 + sizeof size) throw InputError("corrupt replay memory (truncated)");
  std::memcpy(&size, bytes.data() + 4, sizeof size);
  if (size > bytes.size() - 4 - sizeof size) throw InputError("corrupt replay memory (bad length)");
  buffer_ = ReplayBuffer::deserialize(bytes.substr(4 + sizeof size, size));
  general_buffer_ = ReplayBuffer::deserialize(bytes.substr(4 + sizeof size + size));
}

}  // namespace autoblock
