// Budgets counted in work, not wall time (the general search's, region_search.h; the exact search's,
// baselines/optimal_search.h), so that a face decomposes the same on every machine and under any load.
// The wall clock only backs them: past search_wall_backstop(limit) seconds (kSearchWallBackstop times
// the limit, a machine that much slower, and at least kSearchWallFloor more than it), the search stops
// as if its budget were spent.
#pragma once

namespace autoblock {

constexpr double kSearchWallBackstop = 4.0;
constexpr double kSearchWallFloor = 1.0;

// Inputs: time_limit, seconds. Output: the wall-clock backstop in seconds.
inline double search_wall_backstop(double time_limit) {
  const double times = kSearchWallBackstop * time_limit, floor = time_limit + kSearchWallFloor;
  return times > floor ? times : floor;
}

}  // namespace autoblock
