#include "core/region/region_policy.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <tuple>
#include <unordered_map>

#include "core/region/region_candidates.h"
#include "core/region/region_reward.h"

namespace autoblock {

std::unique_lock<std::mutex> lock_general_engine() {
  static std::mutex general_engine;
  return std::unique_lock<std::mutex>(general_engine);
}

namespace {

struct ChordsHash {
  size_t operator()(const std::vector<double>& key) const {
    size_t seed = key.size();
    for (const double x : key) seed ^= std::hash<double>()(x) + 0x9e3779b97f4a7c15ull + (seed << 6) + (seed >> 2);
    return seed;
  }
};

}  // namespace

std::vector<ScoredAction> score_candidates(const Region& part, double face_size, const RegionEpisodeOptions& options,
                                          const std::chrono::steady_clock::time_point* deadline) {
  std::vector<ScoredAction> scored;
  const Complexity complexity = part_complexity(part, options.rules);
  // A full cut is a line: the candidates list an edge's line from both its ends, an axis through
  // aligned vertices from each of them. The line is cut once; the others take its outcome. Lines
  // are keyed by their direction (to 1e-9) and their offset from the origin (to the part's quantum);
  // the value is the outcome's place in scored, or -1 when it made no progress.
  std::map<std::array<long long, 3>, long> lines;
  std::unordered_map<std::vector<double>, long, ChordsHash> chord_sets;  // a set of chords -> the outcome's place in scored, or -1
  for (const RegionAction& action : region_candidates(part)) {
    if (deadline && !scored.empty() && std::chrono::steady_clock::now() > *deadline) break;
    ScoredAction s{action, {}, 0.0};
    if (action.kind == RegionAction::Kind::Template) {
      s.outcome = std::make_shared<const CutOutcome>(CutOutcome{{part}, {}});
      s.reward = region_template_reward(options.reward, part, face_size, options.rules);
    } else {
      std::map<std::array<long long, 3>, long>::iterator line = lines.end();
      if (action.cut.kind == CutKind::Full && !action.cut.forced) {
        const double length = std::hypot(action.cut.direction.x, action.cut.direction.y);
        Point2 u{action.cut.direction.x / length, action.cut.direction.y / length};
        if (u.x < -1e-12 || (std::fabs(u.x) <= 1e-12 && u.y < 0.0)) u = {-u.x, -u.y};
        const double offset = u.x * action.cut.origin.y - u.y * action.cut.origin.x;
        bool inserted = false;
        std::tie(line, inserted) =
            lines.insert({{std::llround(u.x * 1e9), std::llround(u.y * 1e9), std::llround(offset / part.quantum())}, -1});
        if (!inserted) {
          if (line->second < 0) continue;
          s.outcome = scored[static_cast<size_t>(line->second)].outcome;
          s.reward = scored[static_cast<size_t>(line->second)].reward;
          scored.push_back(std::move(s));
          continue;
        }
      }
      // Cuts with the same chords have the same outcome (cut_region_if): the first is cut, the
      // others take its outcome.
      auto same = chord_sets.end();
      std::optional<CutOutcome> outcome = cut_region_if(part, action.cut, [&](const std::vector<Chord>& chords) {
        std::vector<double> key;
        key.reserve(4 * chords.size());
        for (const Chord& c : chords) key.insert(key.end(), {c.a.x, c.a.y, c.b.x, c.b.y});
        bool inserted = false;
        std::tie(same, inserted) = chord_sets.insert({std::move(key), -1});
        return inserted && !chords.empty();  // no chords: no progress
      });
      if (!outcome) {
        if (same == chord_sets.end() || same->second < 0) continue;
        if (line != lines.end()) line->second = same->second;
        s.outcome = scored[static_cast<size_t>(same->second)].outcome;
        s.reward = scored[static_cast<size_t>(same->second)].reward;
        scored.push_back(std::move(s));
        continue;
      }
      if (!makes_progress(complexity, outcome->pieces, options.rules)) continue;
      s.reward = region_cut_reward(options.reward, *outcome, face_size, options.rules);
      s.outcome = std::make_shared<const CutOutcome>(std::move(*outcome));
      if (line != lines.end()) line->second = static_cast<long>(scored.size());
      if (same != chord_sets.end()) same->second = static_cast<long>(scored.size());
    }
    scored.push_back(std::move(s));
  }
  return scored;
}

RegionAction RegionGreedyPolicy::choose(const RegionEpisode& episode) {
  const auto scored = score_candidates(episode.current_part(), episode.face_size(), episode.options());
  const ScoredAction* best = nullptr;
  for (const ScoredAction& s : scored) {
    if (!best || s.reward > best->reward) best = &s;
  }
  return best ? best->action : progress_action(episode.current_part(), episode.options().rules);
}

RegionAction RegionRandomPolicy::choose(const RegionEpisode& episode) {
  // Candidates in random order; the first that changes something is the choice.
  std::vector<RegionAction> candidates = region_candidates(episode.current_part());
  std::shuffle(candidates.begin(), candidates.end(), rng_);
  for (const RegionAction& action : candidates) {
    if (action.kind == RegionAction::Kind::Template ||
        makes_progress(episode.current_part(), cut_region(episode.current_part(), action.cut).pieces, episode.options().rules)) {
      return action;
    }
  }
  return progress_action(episode.current_part(), episode.options().rules);
}

RegionDecomposition episode_decomposition(const RegionEpisode& episode, const std::string& policy) {
  RegionDecomposition result;
  result.policy = policy;
  result.reward = episode.options().reward;
  result.rules = episode.options().rules;
  result.finished = episode.finished();
  result.cuts = episode.cuts();
  result.total_return = episode.total_return();
  result.status = episode.status();
  for (const RegionPiece& piece : episode.queue()) result.unfinished.push_back(piece.region);
  for (const FinishedRegion& f : result.finished) (f.is_template ? result.templates : result.blocks) += 1;
  return result;
}

RegionDecomposition decompose_region(const Region& face, RegionPolicy& policy, RegionEpisodeOptions options) {
  const auto start = std::chrono::steady_clock::now();
  RegionEpisode episode(face, options);
  int policy_steps = 0;
  while (episode.running()) {
    episode.step(policy.choose(episode));
    ++policy_steps;
  }
  // Past the step cap: finish every part left with actions that surely make progress (each removes
  // a hole, a reflex vertex or a corner, so a bounded number of steps is enough).
  if (episode.status() == EpisodeStatus::Truncated) {
    int extra = 0;
    for (const RegionPiece& piece : episode.queue()) extra += 4 * piece.region.vertex_count() + 8;
    episode.extend_steps(extra);
    while (episode.running()) episode.step(progress_action(episode.current_part(), episode.options().rules));
  }
  RegionDecomposition result = episode_decomposition(episode, policy.name());
  result.policy_steps = policy_steps;
  result.time_capped = policy.time_capped();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace autoblock
