#include "core/region/region_policy.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "core/region/region_candidates.h"
#include "core/region/region_reward.h"
#include "core/region/region_search.h"

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
                                          SearchWork* work, size_t keep, bool taper) {
  const Complexity complexity = part_complexity(part, options.rules);
  const long long cost = part.vertex_count();
  auto charge = [&] {
    if (work) work->spent += cost;
  };
  auto past_stop = [&] { return work && work->past(); };
  // Candidates with the same outcome form a group, scored once. A full cut is a line: the
  // candidates list an edge's line from both its ends, an axis through aligned vertices from each of
  // them; lines are keyed by their direction (to 1e-9) and their offset from the origin (to the
  // part's quantum). Cuts with the same chords have the same outcome (cut_region_if): a ray from a
  // vertex to another and the ray back, a full cut whose line runs through the part once and the
  // partial cut along it.
  struct Group {
    RegionCut cut;                              // the first candidate's
    bool scored = false;                        // outcome and reward known
    std::shared_ptr<const CutOutcome> outcome;  // null: no progress
    double reward = 0.0;
    double bound = std::numeric_limits<double>::infinity();  // of the reward (region_cut_reward_bound)
    size_t members = 0;
  };
  std::vector<Group> groups;
  std::vector<std::pair<RegionAction, long>> listed;  // candidates in order, with their group (-1: none)
  std::map<std::array<long long, 3>, long> lines;
  std::unordered_map<std::vector<double>, long, ChordsHash> chord_sets;
  auto score = [&](Group& g, std::optional<CutOutcome> outcome) {
    if (!outcome) {
      charge();
      outcome = cut_region(part, g.cut);
    }
    g.scored = true;
    if (!makes_progress(complexity, outcome->pieces, options.rules)) return;
    g.reward = region_cut_reward(options.reward, *outcome, face_size, options.rules);
    if (taper) g.reward -= pieces_taper_cost(outcome->pieces, options.rules);
    g.outcome = std::make_shared<const CutOutcome>(std::move(*outcome));
  };
  size_t scored_count = 0;  // scored candidates that make progress (with their groups' members)
  for (const RegionAction& action : region_candidates(part)) {
    if (scored_count > 0 && past_stop()) break;
    if (action.kind == RegionAction::Kind::Template) {
      charge();
      Group g;
      g.scored = true;
      g.outcome = std::make_shared<const CutOutcome>(CutOutcome{{part}, {}});
      g.reward = region_template_reward(options.reward, part, face_size, options.rules);
      g.members = 1;
      ++scored_count;
      listed.push_back({action, static_cast<long>(groups.size())});
      groups.push_back(std::move(g));
      continue;
    }
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
        listed.push_back({action, line->second});
        if (line->second >= 0) {
          Group& g = groups[static_cast<size_t>(line->second)];
          ++g.members;
          if (g.outcome) ++scored_count;
        }
        continue;
      }
    }
    // The chords first: a set of chords seen before joins its group; a new one is scored now, or
    // later, in order of its bound, when only the best `keep` candidates are wanted.
    long group = -1;
    bool told = false;
    std::vector<Chord> told_chords;
    charge();
    std::optional<CutOutcome> outcome = cut_region_if(part, action.cut, [&](const std::vector<Chord>& chords) {
      told = true;
      if (chords.empty()) return false;  // separates nothing: no progress
      std::vector<double> key;
      key.reserve(4 * chords.size());
      for (const Chord& c : chords) key.insert(key.end(), {c.a.x, c.a.y, c.b.x, c.b.y});
      const auto [at, inserted] = chord_sets.insert({std::move(key), static_cast<long>(groups.size())});
      group = at->second;
      if (!inserted) return false;
      groups.emplace_back().cut = action.cut;
      told_chords = chords;
      return keep == 0;  // every candidate wanted: scored now
    });
    if (told && group < 0) {  // no chords
      listed.push_back({action, -1});
      if (line != lines.end()) line->second = -1;
      continue;
    }
    if (!told) {
      group = static_cast<long>(groups.size());
      groups.emplace_back().cut = action.cut;
    }
    Group& g = groups[static_cast<size_t>(group)];
    if (outcome) {
      score(g, std::move(outcome));
    } else if (!g.scored && !told_chords.empty()) {
      g.bound = region_cut_reward_bound(options.reward, part, told_chords, options.rules);
    }
    ++g.members;
    if (g.outcome) ++scored_count;
    listed.push_back({action, group});
    if (line != lines.end()) line->second = group;
  }
  // The groups left, most promising first: one whose bound is below the reward of the keep-th best
  // candidate scored so far cannot be among the best keep (ties are scored: they keep their order).
  std::vector<size_t> waiting;
  for (size_t k = 0; k < groups.size(); ++k) {
    if (!groups[k].scored && groups[k].members > 0) waiting.push_back(k);
  }
  std::stable_sort(waiting.begin(), waiting.end(), [&](size_t a, size_t b) { return groups[a].bound > groups[b].bound; });
  auto keep_th_best = [&] {
    std::vector<std::pair<double, size_t>> rewards;
    for (const Group& g : groups) {
      if (g.outcome) rewards.push_back({g.reward, g.members});
    }
    std::sort(rewards.begin(), rewards.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    size_t count = 0;
    for (const auto& [reward, members] : rewards) {
      count += members;
      if (count >= keep) return reward;
    }
    return -std::numeric_limits<double>::infinity();
  };
  double threshold = keep_th_best();
  for (const size_t k : waiting) {
    Group& g = groups[k];
    if (g.bound < threshold - 1e-9) break;
    if (scored_count > 0 && past_stop()) break;
    score(g, std::nullopt);
    if (g.outcome) {
      scored_count += g.members;
      if (g.reward > threshold) threshold = keep_th_best();
    }
  }
  std::vector<ScoredAction> scored;
  for (const auto& [action, group] : listed) {
    if (group < 0) continue;
    const Group& g = groups[static_cast<size_t>(group)];
    if (g.outcome) scored.push_back({action, g.outcome, g.reward});
  }
  return scored;
}

TimedRegionPolicy::TimedRegionPolicy(std::unique_ptr<RegionPolicy> policy, double seconds)
    : policy_(std::move(policy)), seconds_(seconds) {
  if (!policy_) throw std::invalid_argument("TimedRegionPolicy: no policy");
}

RegionAction TimedRegionPolicy::choose(const RegionEpisode& episode) {
  const auto now = std::chrono::steady_clock::now();
  if (face_start_(episode)) {
    capped_ = false;
    deadline_ = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                          std::chrono::duration<double>(seconds_ > 0.0 ? search_wall_backstop(seconds_) : 0.0));
    return policy_->choose(episode);  // its work() counts this face's from here
  }
  if (seconds_ > 0.0 && (policy_->work() > std::llround(kSearchWorkPerSecond * seconds_) || now > deadline_)) {
    capped_ = true;
    return greedy_.choose(episode);
  }
  return policy_->choose(episode);
}

RegionAction RegionGreedyPolicy::choose(const RegionEpisode& episode) {
  const auto scored = score_candidates(episode.current_part(), episode.face_size(), episode.options(), nullptr, 1);
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
  result.work = policy.work();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace autoblock
