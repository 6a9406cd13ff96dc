#include "core/baselines/optimal_search.h"

#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include "core/baselines/greedy_policy.h"
#include "core/common/wall_backstop.h"
#include "core/geometry/part_boundary.h"

namespace autoblock {

OptimalSearch::OptimalSearch(double face_size, double seconds, RewardPreset reward) : face_size_(face_size), reward_(reward) {
  set_budget(seconds);
}

void OptimalSearch::set_budget(double seconds) {
  limited_ = seconds > 0;
  budget_ = limited_ ? std::llround(kOptimalWorkPerSecond * seconds) : 0;
  work_ = 0;
  deadline_ = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                     std::chrono::duration<double>(limited_ ? search_wall_backstop(seconds) : 0.0));
  calls_ = 0;
}

double OptimalSearch::value(const Part& part) { return part.is_rectangle() ? 0.0 : solve(part).value; }

AxisLine OptimalSearch::best_line(const Part& part) { return solve(part).line; }

const OptimalSearch::Entry& OptimalSearch::solve(const Part& part) {
  const auto found = memo_.find(part);
  if (found != memo_.end()) return found->second;
  if (limited_ && (work_ > budget_ || ((++calls_ & 255) == 0 && std::chrono::steady_clock::now() > deadline_))) throw TimeLimit();

  std::set<std::pair<int, int>> lines;  // (direction, index), each line once
  for (const CornerRing& loop : part_boundary(part)) {
    for (const Corner& c : loop) {
      lines.emplace(static_cast<int>(CutDirection::Horizontal), c.j);
      lines.emplace(static_cast<int>(CutDirection::Vertical), c.i);
    }
  }
  work_ += static_cast<long long>(lines.size() + 1) * part.width_cells() * part.height_cells();
  Entry best{-std::numeric_limits<double>::infinity(), AxisLine{}};
  for (const auto& [direction, index] : lines) {
    const AxisLine line{static_cast<CutDirection>(direction), index};
    if (!line_crosses_interior(part, line)) continue;
    const std::vector<Part> pieces = cut_part(part, line);
    double total = cut_reward(reward_, pieces, face_size_);
    for (const Part& piece : pieces) total += value(piece);
    if (total > best.value) best = Entry{total, line};
  }
  return memo_.emplace(part, best).first->second;
}

Action action_on_line(const Episode& episode, const AxisLine& line) {
  const auto& vertices = episode.current_vertices();
  for (int v = 0; v < static_cast<int>(vertices.size()); ++v) {
    const Corner& c = vertices[static_cast<size_t>(v)].corner;
    if ((line.direction == CutDirection::Vertical ? c.i : c.j) == line.index) return Action{v, line.direction};
  }
  throw std::logic_error("the best line passes through no vertex");
}

OptimalPolicy::OptimalPolicy(double face_size, double seconds, RewardPreset reward)
    : search_(face_size, seconds, reward) {}

Action OptimalPolicy::choose(const Episode& episode) {
  if (!capped_) {
    try {
      return action_on_line(episode, search_.best_line(episode.current_part()));
    } catch (const OptimalSearch::TimeLimit&) {
      capped_ = true;
    }
  }
  GreedyPolicy greedy;
  return greedy.choose(episode);
}

}  // namespace autoblock
