// Interval assignment: how many mesh intervals every strip of a blocked face gets (GLPK).
//
// The classic problem (Mitchell 1997) gives every edge of the block model an integer count n_e >= 1
// with, in every block, equal totals on opposite sides (a side may consist of several edges), and
// counts near length / h. Equal totals are not enough for a mesh of rectangles: opposite sides
// must carry nodes at the same positions, and the mesh line of a T-junction must cross the
// neighbours (strip_layout.h). So the unknowns here are the strips' counts n_s, every block-model
// edge being a run of strips (n_e = sum of its strips' n_s). That satisfies the classic
// constraints identically, for every choice of n_s >= 1, and fixes the node positions.
//
// The integer program (solved with GLPK's branch and cut, glp_intopt):
//   candidates  k in K_s for strip s of length L_s: near g_s = L_s / h, a window
//               [max(1, floor(g_s) - 1), ceil(g_s) + 1]; for a strip inside a fixed-count
//               constraint, every k from 1 to that count;
//   variables   y_{s,k} in {0, 1} (strip s gets k intervals), t >= 0;
//   constraints sum_k y_{s,k} = 1                          for every strip s,
//               t >= sum_k d_{s,k} y_{s,k}                  for every strip s,
//               sum_{s in S} sum_k k y_{s,k} = N            for every fixed count (S, N);
//   objective   minimise t + (0.01 / #strips) sum_s sum_k d_{s,k} y_{s,k},
//   with d_{s,k} = |L_s / k - h| / h, the relative deviation of the element size from h.
// So it minimises the largest deviation from h, then the mean, with the true size deviation
// (not |n - g|: for g = 1.45 rounding picks n = 1, size 1.45 h, while n = 2 gives 0.725 h).
// Without fixed counts the strips are independent and the program separates; fixed counts (a
// user's "this edge gets N intervals", as meshing tools offer) couple the strips of an edge, and
// then rounding each strip fails.
#pragma once

#include <string>
#include <vector>

#include "core/mesh/strip_layout.h"

namespace autoblock {

// Largest mesh a request may ask for (quadrilaterals).
constexpr long kMaxMeshQuads = 5'000'000;

// The element size used when none is given: the longer side of the face's bounding box divided by
// this (20 elements along it).
constexpr double kDefaultSizeDivisions = 20.0;

// A fixed count: the strips of one stretch of the block model get `intervals` in total.
struct FixedIntervals {
  std::vector<int> strips;
  int intervals = 1;
  std::string what;  // names the stretch in messages, e.g. "edge (0, 0)-(3, 0)"
};

struct IntervalOptions {
  double target_size = 0.0;  // h > 0, model units
  std::vector<FixedIntervals> fixed;
  long max_quads = kMaxMeshQuads;
  double time_limit = 30.0;  // seconds for GLPK (a general face's: a backstop, see edge_intervals.h)
  // A general face's (edge_intervals.h): simplex iterations GLPK may spend before it has an
  // assignment, past which it gives up (0: no such limit; the time limit alone).
  long first_iterations = 0;
  // A general face's: if set, GLPK's simplex iterations times the program's rows are added to it (what
  // its solves cost, counted rather than timed: mesh_input_face's tries).
  long long* simplex_work = nullptr;
  int min_intervals = 1;     // a general face's model edges (edge_intervals.h): at least this many each
  std::vector<int> edge_minimum;  // a general face's: per model edge, at least this many (empty: none)
  // A general face's: per model edge, a count the program aims at when it is above the edge's length
  // over h (an arc's chord steps); deviations are measured from it, so it is a target, not a bound
  // (empty, or 0: length over h).
  std::vector<double> edge_target;
  // The weight of a targeted edge's deviation in the objective, beside the largest deviation's 1: the
  // program keeps the target unless missing it lowers the largest deviation more than this much.
  double edge_target_weight = 0.1;
};

struct IntervalAssignment {
  std::vector<int> intervals;            // per strip, >= 1
  double target_size = 0.0;              // h
  double max_deviation = 0.0;            // max over strips |L_s / n_s - h|, model units
  double max_relative_deviation = 0.0;   // the same divided by h
  double mean_relative_deviation = 0.0;  // mean over strips of |L_s / n_s - h| / h
  int worst_strip = -1;                  // a strip with the largest deviation
  long quads = 0;                        // sum over cells of n_column * n_row
  bool optimal = true;                   // false when GLPK stopped at its time or iteration limit
};

// Inputs:  layout; options.
// Outputs: the counts that solve the program above, and the deviation figures.
// Throws InputError when h is not a positive finite number, when the mesh would exceed
// max_quads, or when the fixed counts cannot hold (naming the constraint when one alone is
// impossible); std::runtime_error when GLPK fails.
IntervalAssignment assign_intervals(const StripLayout& layout, const IntervalOptions& options);

// Inputs:  layout; a, b, the ends of an axis-parallel stretch along block sides or the boundary
//          (model coordinates, snapped to the face's grid within tolerance); intervals.
// Outputs: the fixed count on the strips that divide it, named "edge (ax, ay)-(bx, by)".
// Throws InputError when the stretch is not axis-parallel, not on the face, or ends inside a
// strip (its ends must be where mesh lines meet it: block corners or crossings of forced lines).
FixedIntervals fixed_intervals_on(const StripLayout& layout, Point2 a, Point2 b, int intervals, double tolerance);

// Inputs: quads, the number of quadrilaterals a mesh would have; estimated, whether that is an
//         estimate (then it may exceed max_quads by half before it counts); h; max_quads.
// Throws InputError ("element size h would need ... quadrilaterals (limit ...)") when it is too many.
void check_quad_limit(double quads, bool estimated, double h, long max_quads);

// Inputs: layout; intervals per strip. Output: the number of quadrilaterals they give.
long quad_count(const StripLayout& layout, const std::vector<int>& intervals);

}  // namespace autoblock
