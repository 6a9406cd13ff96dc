// The local observation at a vertex of a general part (issue 12): the paper's 9 numbers
// (env/observation.h), generalised to any angle.
//
// With v the vertex, p and n the previous and next vertices of its own loop (the region's canonical
// loops run with the part on their left: region.h), c the part's area centroid, W x H its
// axis-aligned bounding box and s = max(W, H), in the face's frame:
//   [0..1] (p - v) / s      [2..3] (n - v) / s      [4..5] (c - v) / s
//   [6]    the true interior angle at v / 360 degrees (in (0, 1): 0.25 at a right corner, 0.75 at a
//          re-entrant right corner, 0.5 at a side vertex or an arc's sample)
//   [7..8] W / s, H / s
// Every number lies in [-1, 1] and none depends on the drawing's units or position. On a
// rectilinear part it is observe_vertex's observation at the same corner (the grid's corners are
// the region's vertices). An arc reaches the part as chords (geometry/circular_arc.h), so along an
// arc p and n are its neighbouring samples.
#pragma once

#include "core/env/observation.h"
#include "core/region/region.h"

namespace autoblock {

// Inputs:  region, not empty; loop (0 the outer ring, k >= 1 hole k - 1) and index within it.
// Outputs: the observation at region.loop(loop)[index].
// Throws std::out_of_range for a loop or index outside the region.
Observation observe_region_vertex(const Region& region, int loop, int index);

// Inputs: region, the vertex's loop and index (as above). Output: the interior angle at it, in
//         degrees, in (0, 360): the turn from the next vertex's direction to the previous one's,
//         counter-clockwise (the part on the loop's left).
double region_interior_angle(const Region& region, int loop, int index);

}  // namespace autoblock
