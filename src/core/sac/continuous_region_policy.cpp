#include "core/sac/continuous_region_policy.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/region/region_candidates.h"
#include "core/region/region_episode.h"

namespace autoblock {

std::vector<float> ContinuousRegionPolicy::vertex_scores(const RegionEpisode& episode) {
  return agent_->vertex_values(*general_state(episode.current_part(), config_.graph));
}

RegionAction ContinuousRegionPolicy::choose(const RegionEpisode& episode) {
  constexpr size_t kTries = 8;  // vertices tried, by value, before progress_action
  if (face_start_(episode)) work_ = 0;
  const Region& part = episode.current_part();
  const BlockRules& rules = episode.options().rules;
  const auto state = general_state(part, config_.graph);
  work_ += kContinuousGraphEdgeWork * state->graph.edge_count();
  const std::vector<float> values = agent_->vertex_values(*state);
  const float finish = template_choice_reward(part, episode.options().reward, episode.face_size(), rules);
  std::vector<size_t> order(values.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return values[a] > values[b]; });
  for (size_t k = 0; k < std::min(order.size(), kTries); ++k) {
    if (!std::isnan(finish) && finish >= values[order[k]]) {
      RegionAction action;
      action.kind = RegionAction::Kind::Template;
      return action;
    }
    RegionAction action;
    action.cut = cut_of_angle(part, static_cast<int>(order[k]), agent_->angle_action(state->observations[order[k]], nullptr));
    work_ += part.vertex_count();
    if (makes_progress(part, episode.outcome_of(action).pieces, rules)) return action;
  }
  if (!std::isnan(finish)) {
    RegionAction action;
    action.kind = RegionAction::Kind::Template;
    return action;
  }
  return progress_action(part, rules);
}

}  // namespace autoblock
