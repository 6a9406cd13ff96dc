// The minimum number of rectangles of any partition of a part: a lower bound on the block count of
// every decomposition (full cuts included).
//
// For a rectilinear region with R re-entrant corners and H holes the minimum is R - L - H + 1,
// where L is the largest number of pairwise disjoint chords (axis-parallel segments inside the
// region joining two re-entrant corners; chords meeting at an end point are not disjoint).
// Horizontal chords never meet each other, nor do vertical ones, so L is the size of a maximum
// independent set of a bipartite graph: chords minus a maximum matching (Konig).
#pragma once

#include "core/geometry/part.h"

namespace autoblock {

// Inputs: part. Output: the minimum number of rectangles partitioning it.
int min_rectangles(const Part& part);

}  // namespace autoblock
