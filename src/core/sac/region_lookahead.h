// One step of lookahead from a general part (issue 12): the candidate actions of the general
// engine (region_candidates.h) that make progress, with the reward each earns and the pieces it
// leaves, and per-vertex summaries of the two best cuts at each vertex: what part_lookahead.h is on
// the grid, for the lookahead agent's value network on general faces.
//
// On the grid a corner has two cuts, horizontal and vertical; a vertex of a general part has many
// (its edges' extensions, bisector, normals, the minimum-area rectangle's axes, diagonals; partial
// and full). Its summary holds the best two by reward (the earlier candidate first among equals),
// in the grid's layout (part_lookahead.h, kVertexLookahead numbers):
//   [0] reflex (0/1)
//   [1..2] reward / lookahead_reward_scale of the best and the second best cut from the vertex
//   [3..4] their N / 4 (pieces left)        [5..6] their blocks / N
// A vertex with fewer than two such cuts gets, for the missing ones, what a cut that separates
// nothing earns (N = 1, no block). Cuts from an edge's midpoint and the template are candidates but
// belong to no vertex. The scale numbers: the part's bounding-box longer side and the square root of
// its area, over the face's size.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/region/region_policy.h"
#include "core/sac/part_lookahead.h"

namespace autoblock {

struct RegionCandidate {
  RegionAction action;
  int vertex = -1;              // the vertex it starts at (loops flattened, Region::loops order), -1: none
  double reward = 0.0;          // under the episode's preset
  int pieces = 0;               // N (1 for the template)
  int blocks = 0;               // pieces that are blocks under the episode's rules
  std::vector<Region> to_cut;   // the pieces that are not blocks
  bool always = false;          // in every shortlist (best_candidates): the O-grid on a part with a hole
                                // or the template on a reflex fillet's corner piece, which finish the
                                // part at a reward far below a cut's (the search expands them too)
};

struct RegionLookahead {
  std::vector<RegionCandidate> candidates;  // score_candidates order
  std::vector<std::array<float, kVertexLookahead>> vertex_features;  // one per vertex, loops flattened
  std::array<float, kPartScale> scale{};
};

// Inputs:  part, not a block; face_size, the longer side of the face's bounding box; options, the
//          episode's (reward preset and block rules). The caller holds lock_general_engine()
//          (region_policy.h), as for any computation on regions.
// Outputs: its lookahead (above). Deterministic.
// taper: each candidate's reward less the taper charge of the blocks it leaves (score_candidates,
//         region_policy.h; the search's ranking under the mesh preset), in the candidates and the
//         summaries alike. work (optional): charged for the candidates measured, as the search's is
//         (SearchWork, never stopped here).
RegionLookahead region_look_ahead(const Region& part, double face_size, const RegionEpisodeOptions& options,
                                  bool taper = false, SearchWork* work = nullptr);

// Inputs:  candidates; keep, how many (0: all).
// Outputs: the indices (increasing) of the keep candidates with the best reward, the earlier among
//          equals, and every candidate marked always; all of them when keep is 0 or at least their
//          count. The actions a lookahead agent values on a general part (deployed: deploy_top_k;
//          trained: train_top_k).
std::vector<size_t> best_candidates(const std::vector<RegionCandidate>& candidates, size_t keep);

// Inputs:  part, not a block; action, a cut of it (any angle: a proposal, cut_proposer.h); face_size;
//          options and taper as region_look_ahead's. The caller holds lock_general_engine().
// Outputs: the candidate it makes (reward, pieces, blocks; vertex: the part's vertex at its origin,
//          or -1), or nothing when it makes no progress (region_candidates.h) or cannot be made.
std::optional<RegionCandidate> region_candidate(const Region& part, const RegionAction& action, double face_size,
                                                const RegionEpisodeOptions& options, bool taper = false);

// Inputs:  candidates (a part's); count. Output: the indices of the best candidate by reward from each
//          of up to count distinct vertices (>= 0), best first: the vertices the best candidates start
//          at, each with its best cut (the earlier candidate among equals).
std::vector<size_t> best_at_vertices(const std::vector<RegionCandidate>& candidates, size_t count);

}  // namespace autoblock
