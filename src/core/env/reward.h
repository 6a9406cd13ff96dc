// The reward of one cut: the paper's Eq. (1).
//
//   R = 3 [ (N / sum_i R_i^2)^(1/2) - (sum_i (A_i - mean A)^2 / sum_i A_i)^(1/2) ]
//       + 10 N_q / N - 5 p(N) - 1
//
// over the N pieces the cut leaves (N = 1 when it changes nothing), N_q of them rectangles; A_i is
// piece i's area and R_i its bounding box's longer over shorter side; p(N) = 1 when N = 1, else 0.
// The area term has units of length, so areas are measured on the whole input face scaled so that
// its bounding box's longer side is 1 (face_size below): the reward does not depend on the
// drawing's units.
#pragma once

#include <vector>

#include "core/geometry/part.h"

namespace autoblock {

// Inputs:  pieces, what the cut left (the part itself when N = 1); face_size, the longer side of
//          the input face's bounding box.
// Outputs: Eq. (1).
double paper_reward(const std::vector<Part>& pieces, double face_size);

}  // namespace autoblock
