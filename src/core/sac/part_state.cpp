#include "core/sac/part_state.h"

#include <stdexcept>

#include "core/geometry/part_boundary.h"

namespace autoblock {

std::shared_ptr<const PartState> make_part_state(const Part& part, const PartStateOptions& options) {
  auto state = std::make_shared<PartState>();
  state->graph = part_graph(part, options.graph);
  const std::vector<CornerRing> loops = part_boundary(part);
  for (int l = 0; l < static_cast<int>(loops.size()); ++l) {
    for (int k = 0; k < static_cast<int>(loops[static_cast<size_t>(l)].size()); ++k) {
      state->observations.push_back(observe_vertex(part, loops, l, k));
    }
  }
  if (state->observations.size() != state->graph.vertex_nodes.size()) {
    throw std::logic_error("make_part_state: graph and observations disagree on the vertices");
  }
  if (!options.lookahead) return state;
  PartLookahead lookahead = look_ahead(part, loops, options.face_size, options.reward);
  const size_t nodes = state->graph.positions.size();
  state->feature_count = kLookaheadFeatures;
  state->features.assign(nodes * kLookaheadFeatures, 0.0f);
  for (size_t n = 0; n < nodes; ++n) {
    float* row = &state->features[n * kLookaheadFeatures];
    for (int k = 0; k < 3; ++k) row[k] = state->graph.features[n][static_cast<size_t>(k)];
    for (int k = 0; k < kPartScale; ++k) row[3 + kVertexLookahead + k] = lookahead.scale[static_cast<size_t>(k)];
  }
  for (size_t v = 0; v < state->graph.vertex_nodes.size(); ++v) {
    float* row = &state->features[static_cast<size_t>(state->graph.vertex_nodes[v]) * kLookaheadFeatures];
    for (int k = 0; k < kVertexLookahead; ++k) row[3 + k] = lookahead.vertex_features[v][static_cast<size_t>(k)];
  }
  state->lines = std::move(lookahead.lines);
  return state;
}

}  // namespace autoblock
