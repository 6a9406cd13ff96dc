#include "core/sac/region_state.h"

#include <stdexcept>
#include <utility>

#include "core/region/region_observation.h"

namespace autoblock {

std::shared_ptr<const RegionPartState> make_region_state(const Region& region, const RegionStateOptions& options) {
  auto state = std::make_shared<RegionPartState>();
  state->graph = region_graph(region, options.graph);
  for (int l = 0; l < region.loop_count(); ++l) {
    for (int k = 0; k < static_cast<int>(region.loop(l).size()); ++k) {
      state->observations.push_back(observe_region_vertex(region, l, k));
    }
  }
  if (state->observations.size() != state->graph.vertex_nodes.size()) {
    throw std::logic_error("make_region_state: graph and observations disagree on the vertices");
  }
  if (!options.lookahead) return state;
  RegionLookahead lookahead = region_look_ahead(region, options.face_size, options.episode, options.taper, options.work);
  set_lookahead_features(*state, lookahead.vertex_features, lookahead.scale);
  state->candidates = std::move(lookahead.candidates);
  return state;
}

}  // namespace autoblock
