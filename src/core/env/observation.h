// The local observation at a model vertex: the paper's 9 numbers, scale-invariant.
//
// With v the vertex, p and n the previous and next corners along its own boundary loop (loops run
// with the part on their left: the outer loop counter-clockwise, holes clockwise), c the part's
// area centroid, W x H its bounding box and s = max(W, H):
//   [0..1] (p - v) / s      [2..3] (n - v) / s      [4..5] (c - v) / s
//   [6]    interior angle / 360 degrees: 0.25 at a convex corner, 0.75 at a re-entrant one
//   [7..8] W / s, H / s
// Every number lies in [-1, 1] and none depends on the drawing's units or position.
#pragma once

#include <array>
#include <vector>

#include "core/geometry/part.h"
#include "core/geometry/part_boundary.h"

namespace autoblock {

constexpr int kObservationSize = 9;
using Observation = std::array<float, kObservationSize>;

// Inputs:  part; loops, part_boundary(part); loop, index: the vertex loops[loop][index].
// Outputs: the observation at that vertex.
Observation observe_vertex(const Part& part, const std::vector<CornerRing>& loops, int loop, int index);

}  // namespace autoblock
