#include "core/sac/sac_policy.h"

#include <algorithm>
#include <numeric>

#include "core/sac/part_state.h"

namespace autoblock {

SacPolicy::SacPolicy(std::shared_ptr<SacAgent> agent, std::string name) : agent_(std::move(agent)), name_(std::move(name)) {}

std::vector<float> SacPolicy::vertex_scores(const Episode& episode) {
  return agent_->vertex_values(*make_part_state(episode.current_part(), agent_->config().graph));
}

Action SacPolicy::choose(const Episode& episode) {
  const auto state = make_part_state(episode.current_part(), agent_->config().graph);
  const std::vector<float> values = agent_->vertex_values(*state);
  std::vector<int> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&values](int a, int b) { return values[static_cast<size_t>(a)] > values[static_cast<size_t>(b)]; });
  auto splits = [&episode](const Action& action) {
    return line_crosses_interior(episode.current_part(), episode.line_of(action));
  };
  const Action none{-1, CutDirection::Horizontal};
  Action fallback = none;
  for (int v : order) {
    const auto p = agent_->direction_probabilities(state->observations[static_cast<size_t>(v)]);
    const CutDirection preferred = p[1] > p[0] ? CutDirection::Vertical : CutDirection::Horizontal;
    const CutDirection other = preferred == CutDirection::Vertical ? CutDirection::Horizontal : CutDirection::Vertical;
    if (splits(Action{v, preferred})) return Action{v, preferred};
    if (fallback.vertex < 0 && splits(Action{v, other})) fallback = Action{v, other};
  }
  // Every part that is not a rectangle has a re-entrant corner, whose two lines both split it.
  return fallback;
}

}  // namespace autoblock
