// The rewards of the general engine: Eq. (1) and the meshing preset, read on regions.
//
// Eq. (1) verbatim (env/reward.h) with "rectangle" read as "block" (block.h) and R_i the aspect
// ratio of piece i's minimum-area enclosing rectangle (block.h); areas scaled by the face's size as
// on the grid. On an axis-aligned rectangle the minimum rectangle is its bounding box, so a block
// scores as the grid engine's rectangle does.
// The meshing preset as on the grid, -(N - 1) - w sum over blocks ln R_i - 3 p(N), plus a shape term
// for blocks that are not rectangles: - kMeshShapeWeight (1 - J_b), J_b the block's scaled Jacobian
// (the smallest sine of its four corner angles: 1 for a rectangle).
// Finishing a convex part with the midpoint template (block.h) is an action too: it earns Eq. (1)
// over its n quads minus kTemplatePenalty (paper), or -(n - 1) - kTemplatePenalty (mesh).
#pragma once

#include <vector>

#include "core/env/reward.h"
#include "core/region/block.h"

namespace autoblock {

constexpr double kMeshShapeWeight = 2.0;
constexpr double kTemplatePenalty = 2.0;

// Inputs: region, a block (block_corners). Output: J_b as above, in (0, 1].
double block_scaled_jacobian(const Region& region, const std::array<int, 4>& corners);

// Inputs:  preset; pieces, what the cut left (the part itself when N = 1); face_size, the longer
//          side of the face's bounding box; rules, what a block is.
// Outputs: the preset's reward for the cut.
double region_cut_reward(RewardPreset preset, const std::vector<Region>& pieces, double face_size,
                         const BlockRules& rules = {});

// Inputs: preset; part, convex; face_size. Output: the reward of finishing it with the template.
double region_template_reward(RewardPreset preset, const Region& part, double face_size);

}  // namespace autoblock
