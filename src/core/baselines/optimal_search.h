// The maximum episode return, by exact search.
//
// A cut's reward depends only on the part it cuts, so the return of an episode is a sum over the
// tree of parts and does not depend on the order parts are cut in:
//   V(P) = 0 for a rectangle, else max over lines L through a corner of P that split P of
//          reward(P, L) + sum of V(piece) over the pieces.
// Cuts that change nothing (N = 1) never help: they leave the part as it was at a negative reward
// (3/R - 6 under Eq. (1), -3 under the mesh preset). V is
// memoised on the part's cells (parts recur across branches), and the search stops with
// OptimalSearch::TimeLimit when its budget runs out.
//
// The budget is counted in work, not wall time, so that a face decomposes the same on every machine
// and under any load: each part solved charges its bounding box's cells for every line tried, and one
// more time (the part's boundary); a budget of s seconds is s * kOptimalWorkPerSecond units, what the
// search got through in a second on the machine its figures were measured on (BENCHMARKS.md, "`auto`'s
// and `optimal`'s search budgets in work"). The wall clock only backs it (search_wall_backstop,
// common/wall_backstop.h).
#pragma once

#include <chrono>
#include <stdexcept>
#include <unordered_map>

#include "core/env/policy.h"
#include "core/env/reward.h"
#include "core/geometry/axis_cut.h"
#include "core/geometry/part.h"

namespace autoblock {

constexpr double kOptimalWorkPerSecond = 6.0e7;

class OptimalSearch {
 public:
  struct TimeLimit : std::runtime_error {
    TimeLimit() : std::runtime_error("the optimal search ran out of time") {}
  };

  // Inputs: face_size, the face's longer bounding-box side (reward scale); seconds, the budget (as
  // work, above) counted from construction (<= 0: unlimited); reward, the preset to maximise.
  OptimalSearch(double face_size, double seconds, RewardPreset reward = RewardPreset::Paper);

  // Inputs: part. Output: V(part). Throws TimeLimit.
  double value(const Part& part);
  // Inputs: part, not a rectangle. Output: the first line reaching V(part). Throws TimeLimit.
  AxisLine best_line(const Part& part);
  size_t memo_size() const { return memo_.size(); }
  // Inputs: seconds, a new budget (as work) counted from now (<= 0: unlimited). The memo is kept:
  // every value in it is exact (a search stopped by TimeLimit memoises nothing it did not finish).
  void set_budget(double seconds);
  // The work done since the last budget was set (or since construction), in units (above).
  long long work() const { return work_; }

 private:
  struct Entry {
    double value;
    AxisLine line;
  };
  const Entry& solve(const Part& part);

  double face_size_;
  RewardPreset reward_;
  bool limited_;
  long long budget_ = 0;  // work units (kOptimalWorkPerSecond times the seconds)
  long long work_ = 0;
  std::chrono::steady_clock::time_point deadline_;  // the wall-clock backstop
  long calls_ = 0;
  std::unordered_map<Part, Entry, PartHash> memo_;
};

// Inputs: episode, running; line, a line through a vertex of its current part.
// Output: the action cutting along that line (throws std::logic_error when no vertex is on it).
Action action_on_line(const Episode& episode, const AxisLine& line);

// Follows OptimalSearch's best lines; when the time budget runs out it finishes greedily and
// time_capped() turns true.
class OptimalPolicy : public Policy {
 public:
  // Inputs: face_size, reward (see OptimalSearch); seconds, the budget for the whole episode.
  OptimalPolicy(double face_size, double seconds, RewardPreset reward = RewardPreset::Paper);
  std::string name() const override { return "optimal"; }
  Action choose(const Episode& episode) override;
  bool time_capped() const override { return capped_; }

 private:
  OptimalSearch search_;
  bool capped_ = false;
};

}  // namespace autoblock
