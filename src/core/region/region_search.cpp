#include "core/region/region_search.h"

#include <algorithm>

#include "core/region/region_candidates.h"
#include "core/region/region_reward.h"

namespace autoblock {

double RegionSearchPolicy::solve(const Region& part, const RegionEpisodeOptions& options, double face_size) {
  if (is_block(part, options.rules)) return 0.0;
  const auto found = memo_.find(part);
  if (found != memo_.end()) return found->second.value;
  const bool late = options_.time_limit > 0.0 && std::chrono::steady_clock::now() > deadline_;
  if (late) capped_ = true;
  // Past the budget, parts are finished greedily: every candidate scored, the best immediate reward
  // taken (no lookahead), which costs about what the greedy policy does on the parts left.
  std::vector<ScoredAction> scored =
      score_candidates(part, face_size, options, !late && options_.time_limit > 0.0 ? &deadline_ : nullptr);
  Entry best;
  if (scored.empty()) {
    best.action = progress_action(part, options.rules);
    // Nothing listed makes progress: the fallback action, valued like any other.
    if (best.action.kind == RegionAction::Kind::Template) {
      best.value = region_template_reward(options.reward, part, face_size, options.rules);
    } else {
      const CutOutcome outcome = cut_region(part, best.action.cut);
      best.value = region_cut_reward(options.reward, outcome, face_size, options.rules);
      if (outcome.pieces.size() >= 2) {
        for (const Region& piece : outcome.pieces) best.value += solve(piece, options, face_size);
      }
    }
    memo_[part] = best;
    return best.value;
  }
  std::stable_sort(scored.begin(), scored.end(), [](const ScoredAction& a, const ScoredAction& b) { return a.reward > b.reward; });
  const size_t width = late ? 1 : static_cast<size_t>(std::max(1, options_.width));
  bool have = false;
  for (size_t i = 0; i < scored.size() && i < width; ++i) {
    // Out of time: the candidates expanded so far decide (one greedy finish per part, not one per
    // candidate left).
    if (have && options_.time_limit > 0.0 && std::chrono::steady_clock::now() > deadline_) {
      capped_ = true;
      break;
    }
    double value = scored[i].reward;
    if (scored[i].action.kind == RegionAction::Kind::Cut) {
      for (const Region& piece : scored[i].outcome.pieces) value += solve(piece, options, face_size);
    }
    if (!have || value > best.value) {
      best = {value, scored[i].action};
      have = true;
    }
  }
  memo_[part] = best;
  return best.value;
}

RegionAction RegionSearchPolicy::choose(const RegionEpisode& episode) {
  if (!started_ || episode.face().hash() != face_hash_ || episode.steps() == 0) {
    memo_.clear();
    face_hash_ = episode.face().hash();
    started_ = true;
    capped_ = false;
    deadline_ = std::chrono::steady_clock::now() +
                std::chrono::microseconds(static_cast<long long>(options_.time_limit * 1e6));
  }
  solve(episode.current_part(), episode.options(), episode.face_size());
  return memo_.at(episode.current_part()).action;
}

}  // namespace autoblock
