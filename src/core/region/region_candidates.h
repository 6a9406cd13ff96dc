// The candidate actions the non-learned policies of the general engine enumerate on a part.
//
// At every vertex v of the part (every loop), with p and n its neighbours along the loop:
//   directions  the extensions of its two edges (v - p, v - n), the bisector of its interior angle
//               (pointing inside), the inward normals of its two edges, the two axes of the part's
//               minimum-area rectangle (both ways), and on a convex part the diagonals to every
//               other vertex but its neighbours;
//   partial     a ray along each direction that enters the interior from v;
//   full        the line along each distinct direction (up to sign) through v (not on a convex
//               part, where the full cut is the partial one);
// and from the midpoint of every edge, the partial cut along the edge's inward normal; on a part with
// two smooth holes or more, for every two whose extents along an axis of the part's minimum-area
// rectangle leave a gap, the full cut across that axis through the gap's middle (it separates them,
// so that each may get the O-grid, block.h).
// At the vertices of a smooth hole (every vertex a side vertex: a circle, a slot, circular_arc.h) only
// the bisector (square to the hole), the others running nearly along it; at another side vertex (an
// arc's sample, a cut's end on an edge) all but its edges' extensions, which run along the boundary.
// Duplicate directions (parallel within 1e-9 rad) are listed once. On a convex part that is not a
// block, on a part with one round hole that the O-grid takes, or on a reflex fillet's corner piece
// (block.h: template_applies), finishing it with the template is a candidate too. Every candidate a
// policy picks from here is a real number angle; a learned policy may choose any other.
//
// Progress: the complexity of a part is (holes, reflex vertices, corners), compared
// lexicographically (corners as in block.h: vertices that are not side vertices). A concave arc's
// open ends count as reflex vertices (a reflex fillet: two; block.h, concave_runs), and so does a
// concave arc closed at both ends that turns by more than kClosedRunLimit: the cuts square to the arc
// at its ends make progress, those along its chords (a fan of slivers) do not. A cut makes
// progress when every piece it leaves is less complex than the part, or is a block. Under rules
// with cut_smooth_parts (block.h) a part without holes or reflex vertices, with fewer than three
// corners, that the smooth template does not take counts kSmoothPartCorners more corners. The
// non-learned policies choose only cuts that make progress (and the template): every sequence of
// such actions ends, so no policy can cut a triangle into a triangle and a quadrilateral forever.
#pragma once

#include <vector>

#include "core/region/region_episode.h"

namespace autoblock {

// Inputs: part, not empty. Output: the candidates above, in a fixed order (vertex by vertex).
std::vector<RegionAction> region_candidates(const Region& part);

constexpr int kSmoothPartCorners = 6;

struct Complexity {
  int holes = 0, reflex = 0, corners = 0;
};
bool operator<(const Complexity& a, const Complexity& b);

// Inputs: part; rules. Output: its complexity.
Complexity part_complexity(const Region& part, const BlockRules& rules = {});

// Inputs: part; pieces, what a cut of it left; rules. Output: true when the cut makes progress.
bool makes_progress(const Region& part, const std::vector<Region>& pieces, const BlockRules& rules = {});
// The same with the part's complexity given (scoring many cuts of one part computes it once).
bool makes_progress(const Complexity& part, const std::vector<Region>& pieces, const BlockRules& rules = {});

// Inputs:  part, not finished (not a block under rules).
// Outputs: an action that makes progress towards blocks, for policies that must finish: while the
//          part has holes, a full cut through a hole's vertex along the bisector of its angle (it
//          opens the hole); else a partial cut square to the boundary at a concave arc's open end (or
//          at a long closed one's middle), or along an edge's extension from a reflex vertex (it
//          removes the reflex vertex); else, on a convex part with five or more corners, a partial
//          cut between two opposite corners; else the template. Each is tried in turn (vertex by
//          vertex) until one makes progress; if none does, the same cuts forced (RegionCut::forced:
//          even one grazing a vertex).
RegionAction progress_action(const Region& part, const BlockRules& rules = {});

}  // namespace autoblock
