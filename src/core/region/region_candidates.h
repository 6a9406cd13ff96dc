// The candidate actions the non-learned policies of the general engine enumerate on a part.
//
// At every vertex v of the part (every loop), with p and n its neighbours along the loop:
//   directions  the extensions of its two edges (v - p, v - n), the bisector of its interior angle
//               (pointing inside), the inward normals of its two edges, the two axes of the part's
//               minimum-area rectangle and the face's X and Y axes (both ways);
//   partial     a ray along each direction that enters the interior from v;
//   full        the line along each distinct direction (up to sign) through v.
// Duplicate directions (parallel within 1e-9 rad) are listed once. On a convex part that is not a
// block, finishing it with the midpoint template is a candidate too. Every candidate a policy picks
// from here is a real number angle; a learned policy may choose any other.
#pragma once

#include <vector>

#include "core/region/region_episode.h"

namespace autoblock {

// Inputs: part, not empty. Output: the candidates above, in a fixed order (vertex by vertex).
std::vector<RegionAction> region_candidates(const Region& part);

// Inputs:  part, not finished (not a block under rules).
// Outputs: an action that surely makes progress towards blocks, for policies that must finish: a
//          full cut along a hole's edge while the part has holes (it opens the hole); else a partial
//          cut along an edge's extension from a reflex vertex (it removes the reflex vertex); else,
//          on a convex part with five or more corners, a partial cut between two opposite corners;
//          else the template.
RegionAction progress_action(const Region& part, const BlockRules& rules = {});

}  // namespace autoblock
