// The eight symmetries of the square (rotations by quarter turns, with or without a mirror) applied
// to a part. Rewards, optimal values and block counts are invariant under them (a quarter turn swaps
// horizontal and vertical cuts), so they multiply training data.
#pragma once

#include "core/geometry/grid_face.h"
#include "core/geometry/part.h"

namespace autoblock {

// Inputs:  part; symmetry in 0..7: bit 0 mirrors x, bits 1-2 count quarter turns (counter-clockwise),
//          applied after the mirror.
// Outputs: the transformed part, on its own transformed grid (whose coordinates are the images of
//          the old ones); symmetry 0 gives an equal copy.
Part transform_part(const Part& part, int symmetry);

}  // namespace autoblock
