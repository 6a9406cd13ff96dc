// The search policy of the general engine: a lookahead over the candidate actions with memoisation
// on parts and a time budget.
//
// The value of a part P is 0 for a block, else the best over its `width` most rewarding candidates
// (region_candidates.h: cuts that make progress, and the template) and its O-grid (which finishes a
// part with a hole: its reward is its value) of
//   reward(action) + sum over the pieces it leaves of value(piece).
// Under the mesh preset (RegionSearchOptions::taper) a cut's reward is also charged for the taper of
// the blocks it leaves (pieces_taper_cost, region_reward.h), in the ranking and in the values: the
// search trades a little return for blocks whose opposite sides are nearer in length. The episode's
// reward does not hold the charge (a policy without lookahead, charged for the blocks it finishes but
// not for the parts it leaves, shies away from finishing them).
// Progress makes the recursion finite; parts are canonical values (region.h), so a part reached by
// two orders of cuts is solved once. When the budget (counted in work) runs out, parts not yet solved are finished
// greedily (every candidate scored, the best immediate reward taken, no lookahead and no taper
// charge: the budget bounds the lookahead, and the greedy finish costs about what the greedy policy
// does on the parts left), and the policy reports time_capped(). Branch and bound: a candidate whose value cannot beat the best
// found so far (its reward plus its pieces' values where already solved, else an upper bound of them:
// under the mesh preset every action costs at least 1 and a part without holes at least half its
// reflex vertices; under Eq. (1) none) is not expanded, and a candidate whose reward's bound from its
// chords (region_cut_reward_bound) shows it cannot be among the `width` best is not cut: the same
// decisions, fewer parts solved and cut.
// A part with kDivideHoles holes or more (a perforated plate) is not searched: it is divided along the
// ligaments between its holes (divide_holes, hole_division.h), by geometry alone, and its pieces are
// solved as parts; only where no line divides it is it searched like any other. A part with one or two
// holes is divided so too where divide_sector finds a line; one with two that a division left (a
// plate's strip whose two holes share a cell's width: searched, such strips ran the plates of scores
// of holes out of time) where divide_holes then finds one with room for both holes' O-grids. A face
// or a search's part with two holes is searched.
#pragma once

#include <chrono>
#include <cmath>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "core/common/wall_backstop.h"
#include "core/region/hole_division.h"
#include "core/region/region_policy.h"

namespace autoblock {

// The search's budget is counted in work (SearchWork, region_policy.h), not wall time, so that a face
// decomposes the same on every machine and under any load: time_limit seconds are
// time_limit * kSearchWorkPerSecond units, what the search's scoring got through in a second on the
// machine its figures were measured on (BENCHMARKS.md, "A budget in work"). The wall clock only backs it
// (search_wall_backstop, common/wall_backstop.h): past that, parts are finished as past the budget.
constexpr double kSearchWorkPerSecond = 7.0e6;

// Past the search's budget, the work each part's greedy scoring may take (see solve), in seconds of
// it: 2 % of the budget, a tenth of that once twice the budget has passed (a face of a thousand
// parts), and never less than kLateSliceFloor.
constexpr double kLateSliceFloor = 0.005;
inline double late_slice(double time_limit, bool past_twice) {
  const double slice = (past_twice ? 0.002 : 0.02) * time_limit;
  return slice > kLateSliceFloor ? slice : kLateSliceFloor;
}

struct RegionSearchOptions {
  int width = 4;              // candidates expanded per part (by immediate reward)
  double time_limit = 2.0;    // seconds per face, as work (kSearchWorkPerSecond); 0: no limit
  bool prune = true;          // branch and bound and bounded scoring, mesh preset (same decisions; false for tests)
  bool taper = true;          // mesh preset: cuts charged for the taper of the blocks they leave, in ranking and values (false: the reward alone)
  bool divide_holes = true;   // a part with kDivideHoles holes or more is divided along its ligaments (hole_division.h), not searched
  // false: a tight cell's O-grid (block.h) is no candidate, and divide_sector leaves no cell for one
  // (one of `autoblock mesh`'s tries, kSearchTries: valuing its few blocks, the search took it where a
  // hole near the face's edge was better cut to the edge).
  bool tight_ogrid = true;
};

class RegionSearchPolicy : public RegionPolicy {
 public:
  explicit RegionSearchPolicy(RegionSearchOptions options = {})
      : options_(options), budget_(limited() ? std::llround(kSearchWorkPerSecond * options.time_limit) : 0) {}
  std::string name() const override { return "search"; }
  RegionAction choose(const RegionEpisode& episode) override;
  bool time_capped() const override { return capped_; }
  long long work() const override { return work_.spent; }
  // Parts solved so far (for reports and tests).
  size_t solved_parts() const { return memo_.size(); }
  // Candidates not expanded because their value's upper bound could not beat the best (mesh preset).
  size_t pruned_candidates() const { return pruned_; }

 private:
  struct Entry {
    double value = 0.0;
    RegionAction action;
  };
  double solve(const Region& part, const RegionEpisodeOptions& options, double face_size);

  RegionSearchOptions options_;
  std::unordered_map<Region, Entry, RegionHash> memo_;
  // The centre of a divided part's arcs, for its pieces (hole_division.h: a piece's own arcs may be
  // too short to find it).
  std::unordered_map<Region, Point2, RegionHash> centres_;
  // The pieces a hole division left (a plate's strips): those with two holes that divide_sector does
  // not divide go to divide_holes too.
  std::unordered_set<Region, RegionHash> divided_;
  FaceStart face_start_;
  bool capped_ = false;
  size_t pruned_ = 0;
  SearchWork work_;
  long long budget_;      // work units (kSearchWorkPerSecond times the limit; 0 without one)
  std::chrono::steady_clock::time_point backstop_;
  bool limited() const { return options_.time_limit > 0.0; }
  // Past the budget, or past the wall clock's backstop.
  bool late() const;
};

}  // namespace autoblock
