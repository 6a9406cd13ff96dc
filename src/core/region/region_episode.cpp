#include "core/region/region_episode.h"

#include <stdexcept>

#include "core/region/region_reward.h"

namespace autoblock {

std::string action_kind_name(const RegionAction& action) {
  return action.kind == RegionAction::Kind::Template ? "template" : cut_kind_name(action.cut.kind);
}

RegionEpisode::RegionEpisode(const Region& face, RegionEpisodeOptions options) : face_(face), options_(options) {
  if (face.is_empty()) throw std::invalid_argument("RegionEpisode: empty face");
  face_size_ = face.bbox().longer_side();
  if (options_.max_steps <= 0) options_.max_steps = 10 * face.vertex_count() + 10;
  if (options_.face_rules && options_.reward == RewardPreset::Mesh) {
    options_.rules = mesh_block_rules(face.loops(), options_.corner_fraction);
    options_.rules.cut_smooth_parts = options_.cut_smooth_parts;
  }
  std::vector<int> ids;
  push(face, &ids);
  if (queue_.empty()) status_ = EpisodeStatus::Complete;
}

void RegionEpisode::push(Region region, std::vector<int>* ids) {
  const int id = next_id_++;
  ids->push_back(id);
  if (const auto corners = block_corners(region, options_.rules)) {
    finished_.push_back({id, std::move(region), false, *corners});
  } else {
    queue_.push_back({id, std::move(region)});
  }
}

CutOutcome RegionEpisode::outcome_of(const RegionAction& action) const {
  if (action.kind == RegionAction::Kind::Template) return {{current_part()}, {}};
  return cut_region(current_part(), action.cut);
}

double RegionEpisode::reward_of(const RegionAction& action, const CutOutcome& outcome) const {
  if (action.kind == RegionAction::Kind::Template) return region_template_reward(options_.reward, current_part(), face_size_, options_.rules);
  return region_cut_reward(options_.reward, outcome, face_size_, options_.rules);
}

void RegionEpisode::extend_steps(int extra) {
  options_.max_steps += extra;
  if (status_ == EpisodeStatus::Truncated && !queue_.empty() && steps() < options_.max_steps) status_ = EpisodeStatus::Running;
}

const RegionCutRecord& RegionEpisode::step(const RegionAction& action) { return step(action, outcome_of(action)); }

const RegionCutRecord& RegionEpisode::step(const RegionAction& action, CutOutcome outcome) {
  if (!running()) throw std::logic_error("RegionEpisode::step: the episode has ended");
  RegionCutRecord record;
  record.part_id = current_part_id();
  record.action = action;
  record.reward = reward_of(action, outcome);
  if (action.kind == RegionAction::Kind::Template) {
    if (!template_applies(current_part())) throw std::logic_error("RegionEpisode::step: the template needs a convex part or one with a round hole");
    finished_.push_back({record.part_id, current_part(), true, {}});
    record.children = {record.part_id};
    queue_.pop_front();
  } else if (outcome.pieces.size() < 2) {
    record.children = {record.part_id};
    queue_.push_back(queue_.front());  // unchanged: back of the queue, as on the grid
    queue_.pop_front();
  } else {
    queue_.pop_front();
    record.n_parts = static_cast<int>(outcome.pieces.size());
    record.chords = std::move(outcome.chords);
    for (Region& piece : outcome.pieces) push(std::move(piece), &record.children);
  }
  return_ += record.reward;
  cuts_.push_back(std::move(record));
  if (queue_.empty()) {
    status_ = EpisodeStatus::Complete;
  } else if (steps() >= options_.max_steps) {
    status_ = EpisodeStatus::Truncated;
  }
  return cuts_.back();
}

}  // namespace autoblock
