#include "core/baselines/greedy_policy.h"

#include <limits>
#include <map>
#include <utility>

namespace autoblock {

Action GreedyPolicy::choose(const Episode& episode) {
  // Vertices on one line make the same cut: evaluate each line once.
  std::map<std::pair<int, int>, double> reward_of_line;
  Action best;
  double best_reward = -std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(episode.current_vertices().size());
  for (int v = 0; v < n; ++v) {
    for (CutDirection d : {CutDirection::Horizontal, CutDirection::Vertical}) {
      const Action action{v, d};
      const AxisLine line = episode.line_of(action);
      const auto key = std::make_pair(static_cast<int>(d), line.index);
      auto found = reward_of_line.find(key);
      if (found == reward_of_line.end()) {
        found = reward_of_line.emplace(key, episode.reward_of(episode.pieces_of(action))).first;
      }
      if (found->second > best_reward) {
        best_reward = found->second;
        best = action;
      }
    }
  }
  return best;
}

}  // namespace autoblock
