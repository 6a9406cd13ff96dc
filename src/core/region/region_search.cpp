#include "core/region/region_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/region/region_candidates.h"
#include "core/region/region_reward.h"

namespace autoblock {
namespace {

// An upper bound of a part's value (the best return of finishing it), for pruning: under the mesh
// preset every action costs at least 1 (a cut leaving N >= 2 pieces earns at most -(N - 1), the
// template at most -2), and a part without holes needs a chord ending at each of its reflex vertices,
// each chord ending at two at most and costing 1. Eq. (1) can be positive: no bound (+infinity).
double value_upper_bound(const Region& part, const RegionEpisodeOptions& options) {
  if (options.reward != RewardPreset::Mesh) return std::numeric_limits<double>::infinity();
  if (is_block(part, options.rules)) return 0.0;
  if (!part.holes().empty()) return -1.0;
  const int reflex = part_complexity(part, options.rules).reflex;
  return -std::max(1.0, std::ceil(0.5 * reflex));
}

}  // namespace

bool RegionSearchPolicy::late() const {
  return limited() && (work_.spent >= budget_ || std::chrono::steady_clock::now() > backstop_);
}

double RegionSearchPolicy::solve(const Region& part, const RegionEpisodeOptions& options, double face_size) {
  if (is_block(part, options.rules)) return 0.0;
  const auto found = memo_.find(part);
  if (found != memo_.end()) return found->second.value;
  const bool late_now = late();
  if (late_now) capped_ = true;
  if (options_.divide_holes && !part.holes().empty()) {
    const bool many = static_cast<int>(part.holes().size()) >= kDivideHoles;
    const auto inherited = centres_.find(part);
    const std::optional<Point2> hint = inherited != centres_.end() ? std::optional<Point2>(inherited->second) : std::nullopt;
    std::optional<HoleDivision> division = many ? divide_holes(part, hint) : divide_sector(part, hint, options_.tight_ogrid);
    if (!division && part.holes().size() == 2 && divided_.count(part) > 0) division = divide_holes(part, hint, true);
    if (division) {
      if (const std::optional<Point2> centre = division->centre ? division->centre : hint) {
        for (const Region& piece : division->outcome.pieces) centres_.emplace(piece, *centre);
      }
      for (const Region& piece : division->outcome.pieces) divided_.insert(piece);
      Entry entry;
      entry.action = {RegionAction::Kind::Cut, division->cut};
      entry.value = region_cut_reward(options.reward, division->outcome, face_size, options.rules);
      for (const Region& piece : division->outcome.pieces) entry.value += solve(piece, options, face_size);
      memo_[part] = entry;
      return entry.value;
    }
  }
  // Past the budget, parts are finished greedily: the best immediate reward taken (no lookahead),
  // which costs about what the greedy policy does on the parts left. Each part's scoring then stops
  // after its slice (late_slice: a part of hundreds of vertices, a plate with scores of holes, has
  // thousands of candidates, each cut costing as much again: scoring them all took minutes; a usual
  // part's all fit in the slice, and the search finishes as greedy would).
  // Only candidates that can be among the `width` best are scored (with pruning on: the same ones).
  const size_t width = late_now ? 1 : static_cast<size_t>(std::max(1, options_.width));
  const bool taper = options_.taper && !late_now && options.reward == RewardPreset::Mesh;
  work_.stop = !limited() ? 0
               : late_now ? work_.spent + std::llround(kSearchWorkPerSecond *
                                                       late_slice(options_.time_limit, work_.spent > 2 * budget_))
                          : budget_;
  std::vector<ScoredAction> scored = score_candidates(part, face_size, options, &work_, options_.prune ? width : 0, taper);
  // Without tight O-grids: a tight cell's template is dropped (the O-grid only measured where the
  // template is among the candidates).
  auto is_template = [](const ScoredAction& s) { return s.action.kind == RegionAction::Kind::Template; };
  if (!options_.tight_ogrid && part.holes().size() == 1 && std::any_of(scored.begin(), scored.end(), is_template) &&
      tight_ogrid_template(part, options.rules)) {
    scored.erase(std::remove_if(scored.begin(), scored.end(), is_template), scored.end());
  }
  Entry best;
  if (scored.empty()) {
    best.action = progress_action(part, options.rules);
    // Nothing listed makes progress: the fallback action, valued like any other.
    if (best.action.kind == RegionAction::Kind::Template) {
      best.value = region_template_reward(options.reward, part, face_size, options.rules);
    } else {
      const CutOutcome outcome = cut_region(part, best.action.cut);
      best.value = region_cut_reward(options.reward, outcome, face_size, options.rules);
      if (taper) best.value -= pieces_taper_cost(outcome.pieces, options.rules);
      if (outcome.pieces.size() >= 2) {
        for (const Region& piece : outcome.pieces) best.value += solve(piece, options, face_size);
      }
    }
    memo_[part] = best;
    return best.value;
  }
  std::stable_sort(scored.begin(), scored.end(), [](const ScoredAction& a, const ScoredAction& b) { return a.reward > b.reward; });
  bool have = false;
  for (size_t i = 0; i < scored.size(); ++i) {
    // The `width` best by immediate reward, and the O-grid (a template on a part with a hole) or the
    // template on a reflex fillet's corner piece (a part with a concave run, block.h): it finishes
    // the part, so its reward is its whole value, far below a cut's reward and far above the cuts'
    // sum. (Every template expanded so took the usual template on chamfered parts, keeping their
    // 135-degree corners whole: 0.71 on every chamfered union.)
    if (i >= width && !(scored[i].action.kind == RegionAction::Kind::Template &&
                        (!part.holes().empty() || !concave_runs(part.outer()).empty()))) {
      continue;
    }
    // Out of time: the candidates expanded so far decide (one greedy finish per part, not one per
    // candidate left).
    if (have && late()) {
      capped_ = true;
      break;
    }
    double value = scored[i].reward;
    // Branch and bound: a candidate whose best possible value cannot beat the best found is not
    // expanded (the decision is the same; the values compared are exact).
    if (have && options_.prune) {
      double bound = value;
      if (scored[i].action.kind == RegionAction::Kind::Cut) {
        for (const Region& piece : scored[i].outcome->pieces) {
          const auto known = memo_.find(piece);
          bound += known != memo_.end() ? known->second.value : value_upper_bound(piece, options);
        }
      }
      if (!(bound > best.value)) {
        ++pruned_;
        continue;
      }
    }
    if (scored[i].action.kind == RegionAction::Kind::Cut) {
      for (const Region& piece : scored[i].outcome->pieces) value += solve(piece, options, face_size);
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
  if (face_start_(episode)) {
    memo_.clear();
    centres_.clear();
    divided_.clear();
    capped_ = false;
    pruned_ = 0;
    work_ = SearchWork{};
    backstop_ = std::chrono::steady_clock::now() +
                std::chrono::microseconds(std::llround(search_wall_backstop(options_.time_limit) * 1e6));
  }
  solve(episode.current_part(), episode.options(), episode.face_size());
  return memo_.at(episode.current_part()).action;
}

}  // namespace autoblock
