// Interval assignment on a general block model (block_model.h): how many mesh intervals every model
// edge gets (GLPK).
//
// The classic integer program (Mitchell 1997) on the model's edges, solved with GLPK's branch and cut:
//   variables   n_e >= 1 (or options.min_intervals) integer per model edge e of length L_e, and t_e, T >= 0;
//   constraints sum of n_e over side 0 = over side 2, and side 1 = side 3, for every block (a side is
//               a chain of edges: a T-junction splits it); sum over the edges of a fixed stretch = N;
//               t_e >= f_e(n_e), T >= t_e;
//   objective   minimise T + (0.01 / #edges) sum_e t_e: the largest deviation first, then the mean,
//   with f_e(n) = max(g_e / n, n / g_e) - 1, g_e = L_e / h: the factor by which the edge's element
//   size L_e / n is off the target h, minus one. f_e is convex in n, so t_e >= f_e(n_e) is the set of
//   secants between breakpoints: every integer from ceil(g_e) + 1 down to 10 (exact there), then
//   breakpoints 10 % apart down to 1 (between those the secant overestimates f_e slightly), plus the
//   line n / g_e - 1 beyond ceil(g_e). Unlike the strips of a rectilinear face
//   (interval_assignment.h), opposite sides of a general block may differ in length (a trapezoid), so
//   counts are not confined to a window around L_e / h: the program may give a short side as many
//   intervals as its long opposite side needs.
// Reported deviations are those of interval_assignment.h (|L_e / n_e - h| / h), over edges.
#pragma once

#include <stdexcept>
#include <vector>

#include "core/mesh/block_model.h"
#include "core/mesh/interval_assignment.h"

namespace autoblock {

// GLPK's branch and bound finds a good assignment at once on every model measured, then may spend
// long proving it best: its best once kIntervalQuickIterations simplex iterations have passed since its
// first assignment stands. Counted in iterations, not seconds, so that a face gets the same counts on
// every machine and under any load (a plate's program of 7 000 rows found a second, better
// assignment 0.73 s in: a one-second limit kept it or not as the machine was busy). A second pass
// (mesh_pipeline.cpp) gives up a program with no assignment after as many iterations.
// IntervalOptions::time_limit bounds the whole as a backstop.
constexpr long kIntervalQuickIterations = 4000;

// Inputs:  model; a, b, the ends of a stretch along model edges (straight, within tolerance);
//          intervals, its count; tolerance.
// Outputs: the fixed count on the model edges that make up the stretch (FixedIntervals::strips holds
//          edge ids), named "edge (ax, ay)-(bx, by)".
// Throws InputError when the stretch is not made of whole model edges (its ends must be model
//          vertices: corners of blocks or T-junctions) or the count is below 1.
FixedIntervals fixed_edge_intervals(const BlockModel& model, Point2 a, Point2 b, int intervals, double tolerance);

// The blocks themselves admit no counts (opposite sides of some block cannot be equal, whatever the
// size): no user's doing, a fault of the block model.
class NoIntervalAssignment : public std::runtime_error {
 public:
  NoIntervalAssignment()
      : std::runtime_error("the blocks admit no interval assignment (opposite sides of some block cannot get equal counts)") {}
};

// Inputs:  model; options (target size h, fixed counts over edges, the quad limit, GLPK's iterations:
//          kIntervalQuickIterations past its first assignment, options.first_iterations before it,
//          options.time_limit in all).
// Outputs: the counts per model edge (IntervalAssignment::intervals indexed by edge, worst_strip an
//          edge) and the deviation figures.
// Throws InputError when h is not a positive finite number, the mesh would exceed max_quads or the
//          fixed counts cannot hold; NoIntervalAssignment when the blocks admit none; std::runtime_error
//          when GLPK fails.
IntervalAssignment assign_edge_intervals(const BlockModel& model, const IntervalOptions& options);

// Inputs: model; intervals per edge. Output: the number of quadrilaterals they give.
long quad_count(const BlockModel& model, const std::vector<int>& intervals);

// Inputs: side; intervals per edge. Output: the side's interval total.
int side_intervals(const ModelSide& side, const std::vector<int>& intervals);

}  // namespace autoblock
