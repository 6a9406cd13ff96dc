#include "core/sac/part_state.h"

#include <stdexcept>

#include "core/geometry/part_boundary.h"

namespace autoblock {

std::shared_ptr<const PartState> make_part_state(const Part& part, const GraphOptions& options) {
  auto state = std::make_shared<PartState>();
  state->graph = part_graph(part, options);
  const std::vector<CornerRing> loops = part_boundary(part);
  for (int l = 0; l < static_cast<int>(loops.size()); ++l) {
    for (int k = 0; k < static_cast<int>(loops[static_cast<size_t>(l)].size()); ++k) {
      state->observations.push_back(observe_vertex(part, loops, l, k));
    }
  }
  if (state->observations.size() != state->graph.vertex_nodes.size()) {
    throw std::logic_error("make_part_state: graph and observations disagree on the vertices");
  }
  return state;
}

}  // namespace autoblock
