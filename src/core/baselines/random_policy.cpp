#include "core/baselines/random_policy.h"

#include <vector>

namespace autoblock {

RandomPolicy::RandomPolicy(std::uint64_t seed, bool splitting_only) : rng_(seed), splitting_only_(splitting_only) {}

Action RandomPolicy::choose(const Episode& episode) {
  const int n = static_cast<int>(episode.current_vertices().size());
  std::vector<Action> candidates;
  for (int v = 0; v < n; ++v) {
    for (CutDirection d : {CutDirection::Horizontal, CutDirection::Vertical}) {
      const Action action{v, d};
      if (!splitting_only_ || line_crosses_interior(episode.current_part(), episode.line_of(action))) {
        candidates.push_back(action);
      }
    }
  }
  // Every non-rectangular part has a re-entrant corner, whose lines both split it.
  std::uniform_int_distribution<size_t> pick(0, candidates.size() - 1);
  return candidates[pick(rng_)];
}

}  // namespace autoblock
