// The corners of a part, in order along its boundary loops: the part's model vertices.
#pragma once

#include <vector>

#include "core/geometry/part.h"

namespace autoblock {

struct Corner {
  int i = 0, j = 0;     // grid point (grid.xs[i], grid.ys[j])
  bool reflex = false;  // interior angle 270 degrees (re-entrant); otherwise 90 degrees
};

// One closed boundary loop with the part on its left.
using CornerRing = std::vector<Corner>;

// Inputs:  part.
// Outputs: its boundary loops, corners only (collinear edges are merged by construction). Loop 0
//          is the outer loop, counter-clockwise; the holes follow, clockwise. Each loop starts at
//          its lowest, then leftmost corner; holes are ordered by that corner (lowest, then
//          leftmost), so the order is canonical.
std::vector<CornerRing> part_boundary(const Part& part);

}  // namespace autoblock
