// The rewards of the general engine: Eq. (1) and the meshing preset, read on regions.
//
// Eq. (1) verbatim (env/reward.h) with "rectangle" read as "block" (block.h) and R_i the aspect
// ratio of piece i's minimum-area enclosing rectangle (block.h); areas scaled by the face's size as
// on the grid. On an axis-aligned rectangle the minimum rectangle is its bounding box, so a block
// scores as the grid engine's rectangle does.
// The meshing preset as on the grid, -(N - 1) - w sum over blocks ln R_i - 3 p(N), plus a shape term
// for the corners the cut creates: - kMeshShapeWeight (1 - J_new), J_new the smallest sine of the
// pieces' corner angles at the ends of the cut's chords (side vertices, within the flat tolerance of
// 180 degrees, do not count): 1 when the cut meets the boundary at right angles, near 0 for a
// sliver. The face's own corners are not the cut's doing and do not count.
// Finishing a convex part with the template (block.h) is an action too: it earns Eq. (1)
// over its n quads minus kTemplatePenalty (paper), or -(n - 1) - kTemplatePenalty - kMeshShapeWeight
// (1 - J_new) (mesh), J_new the smallest sine of its quads' corners at the feet and the centre (the
// corners it creates; a quad's corner at the centre is 180 degrees minus the part's corner, so a
// template on a part with a sharp or a nearly flat corner pays for it) and at the part's corners
// larger than a block may have (kept whole in one quad).
#pragma once

#include <array>
#include <vector>

#include "core/env/reward.h"
#include "core/region/block.h"
#include "core/region/region_cut.h"

namespace autoblock {

constexpr double kMeshShapeWeight = 6.0;
constexpr double kTemplatePenalty = 2.0;
constexpr double kMeshTaperWeight = 1.0;
constexpr double kMeshTaperFrom = 3.0;

// Inputs: block, a region; corners, its four corners (block_corners). Output: the larger of the two
//         ratios of opposite sides' lengths along the boundary (>= 1; 1 for a parallelogram).
double block_taper(const Region& block, const std::array<int, 4>& corners);

// Inputs: block, a region; corners, its four corners. Output: what the search (region_search.h)
//         charges a cut for a block it leaves with taper T (block_taper), under the mesh preset:
//         kMeshTaperWeight ln(T / kMeshTaperFrom) when T exceeds kMeshTaperFrom, else 0. A mapped mesh
//         puts as many intervals on the short side as on the long one: a wedge to a rounded tip (a
//         short arc, one chord to the engine) crowds its quads against the tip, where they meet the
//         straight edges at nearly 180 degrees. Not part of the reward: a policy without lookahead
//         charged for the blocks it finishes but not for the parts it leaves shies away from finishing
//         (the greedy policy made 50-part decompositions of 20-vertex polygons, 28 quads inverted).
double block_taper_cost(const Region& block, const std::array<int, 4>& corners);

// Inputs: pieces, what a cut left; rules. Output: the sum of block_taper_cost over the pieces that
//         are blocks (0 for fewer than two pieces: no cut).
double pieces_taper_cost(const std::vector<Region>& pieces, const BlockRules& rules = {});

// Inputs:  preset; outcome, what the cut left (the part itself when N = 1) and its chords;
//          face_size, the longer side of the face's bounding box; rules, what a block is.
// Outputs: the preset's reward for the cut.
double region_cut_reward(RewardPreset preset, const CutOutcome& outcome, double face_size, const BlockRules& rules = {});

// Inputs:  preset; part, a region without holes; chords, a cut's (cut_region_if tells them before
//          the pieces are made); rules.
// Outputs: an upper bound of region_cut_reward for any outcome with these chords: under the mesh
//          preset -(number of chords across the part) when there are several (a chord that is an
//          edge of the part, where a full cut's line runs along the boundary, does not count), and
//          for one -1 - kMeshShapeWeight (1 - J), J an upper bound of J_new read from the angles the
//          chord makes at its ends with the part's edges (widened by what rounding the pieces to the
//          lattice can change them by, and 1 for an angle near a side vertex's or above); +infinity
//          under Eq. (1), for a part with holes, or for no chord across.
double region_cut_reward_bound(RewardPreset preset, const Region& part, const std::vector<Chord>& chords,
                               const BlockRules& rules = {});

// Inputs: preset; part, convex; face_size; rules, what a block is (a corner above its largest a
//         template keeps whole in one quad, and pays for). Output: the reward of finishing it with
//         the template.
double region_template_reward(RewardPreset preset, const Region& part, double face_size, const BlockRules& rules = {});

}  // namespace autoblock
