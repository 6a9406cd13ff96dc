// What an agent sees of a part of a general face (issue 12): part_state.h's state made from a
// region. Its graph (region_graph.h), the paper's 9 numbers at every vertex (region_observation.h)
// and, with lookahead, the grid's node-feature layout from the region's lookahead
// (region_lookahead.h) and its candidate actions. A region's state is a PartState, so the value
// network, the batching and the agents read it as they read a grid part's.
#pragma once

#include <memory>
#include <vector>

#include "core/graph/region_graph.h"
#include "core/sac/part_state.h"
#include "core/sac/region_lookahead.h"

namespace autoblock {

struct RegionStateOptions {
  GraphOptions graph;
  bool lookahead = false;          // add lookahead features and candidates
  RegionEpisodeOptions episode;    // lookahead: the reward preset and block rules to look ahead with
  double face_size = 1.0;          // lookahead: the longer side of the face's bounding box
  bool taper = false;              // lookahead: rewards less the taper charge (region_look_ahead)
  SearchWork* work = nullptr;      // lookahead: charged for the candidates measured (not part of the state)
};

struct RegionPartState : PartState {
  std::vector<RegionCandidate> candidates;  // lookahead only: the actions that make progress
};

// Inputs:  region, not empty; options. With lookahead the region is not a block and the caller
//          holds lock_general_engine() (region_policy.h).
// Outputs: its state: observations in region.loops() order (graph.vertex_nodes order).
std::shared_ptr<const RegionPartState> make_region_state(const Region& region, const RegionStateOptions& options);

}  // namespace autoblock
