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

#include <string>
#include <vector>

#include "core/geometry/part.h"

namespace autoblock {

// Which reward a cut earns: the paper's Eq. (1), or the meshing preset (mesh_reward below).
enum class RewardPreset { Paper, Mesh };

// "paper" or "mesh".
std::string reward_preset_name(RewardPreset preset);
// Inputs: name, "paper" or "mesh". Output: the preset. Throws InputError for other names.
RewardPreset reward_preset_by_name(const std::string& name);

// Inputs:  the N >= 1 pieces' areas (already scaled by the face's size), their aspect ratios R_i,
//          and how many of them are finished blocks (N_q).
// Outputs: Eq. (1). The grid engine and the general engine (region/region_reward.h) both use it.
double equation_one(const std::vector<double>& areas, const std::vector<double>& aspect_ratios, int blocks);

// Inputs:  pieces, what the cut left (the part itself when N = 1); face_size, the longer side of
//          the input face's bounding box.
// Outputs: Eq. (1).
double paper_reward(const std::vector<Part>& pieces, double face_size);

// The meshing preset, for few and fat blocks. A cut that leaves N pieces costs one unit per new
// piece, and every piece that is a finished block (a rectangle) costs mesh_thin_weight * ln R_i
// for its aspect ratio R_i; a cut that changes nothing costs 3:
//   R = -(N - 1) - mesh_thin_weight * sum over rectangles ln R_i - 3 p(N)
// An episode's return is then minus (blocks - 1 + mesh_thin_weight * sum over blocks ln R_b +
// 3 * wasted cuts): maximising it minimises the block count first and thinness second.
constexpr double kMeshThinWeight = 0.5;
double mesh_reward(const std::vector<Part>& pieces);

// Inputs: preset; pieces, face_size as above. Output: the preset's reward.
double cut_reward(RewardPreset preset, const std::vector<Part>& pieces, double face_size);

}  // namespace autoblock
