// The symmetries of the plane applied to a part of a general face: a turn by any angle, with or
// without a mirror. What the engine computes on a part is invariant under them when the face's size
// and block rules are kept: every candidate (region_candidates.h) is built from the part's own
// edges, angles and minimum-area rectangle (no axis of the face's frame is special), rewards read
// areas, aspect ratios of minimum-area rectangles and angles, and blocks are told by angles. So a
// remembered part shown turned teaches the value network the same value (lookahead_agent.h, issue
// 12), up to the lattice: the turned loops are snapped again, which moves a point by at most half
// the quantum.
#pragma once

#include "core/region/region.h"

namespace autoblock {

// Inputs:  region, not empty; angle, radians (counter-clockwise); mirror, true to mirror x first.
// Outputs: the region mirrored (x -> -x about the centre of its bounding box) when asked, then turned
//          by angle about that centre, on the same lattice (its quantum). Orientation and the
//          canonical form are restored (region.h). angle 0 without a mirror gives an equal region.
Region transform_region(const Region& region, double angle, bool mirror);

}  // namespace autoblock
