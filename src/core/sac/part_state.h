// What an agent sees of a part: its graph (for the value network), the local observation at every
// model vertex (for the actor and critics), in Episode::current_vertices order, and, for the
// lookahead agent, node features with one cut of lookahead and the candidate cuts themselves.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/env/observation.h"
#include "core/env/reward.h"
#include "core/geometry/part.h"
#include "core/graph/part_graph.h"
#include "core/sac/part_lookahead.h"

namespace autoblock {

struct PartStateOptions {
  PartStateOptions(GraphOptions graph_options = {}) : graph(graph_options) {}  // NOLINT: implicit on purpose
  GraphOptions graph;
  bool lookahead = false;                     // add lookahead features and candidate cuts
  RewardPreset reward = RewardPreset::Paper;  // lookahead: the rewards to look ahead with
  double face_size = 1.0;                     // lookahead: GridFace::size of the part's face
};

// Node features: the paper's 3 one-hot kinds; with lookahead also kVertexLookahead numbers at the
// model-vertex nodes (zero elsewhere) and kPartScale numbers at every node.
constexpr int kLookaheadFeatures = 3 + kVertexLookahead + kPartScale;

struct PartState {
  PartGraph graph;
  std::vector<Observation> observations;  // one per model vertex, graph.vertex_nodes order
  int feature_count = 3;
  std::vector<float> features;            // node-major [nodes x feature_count]; empty: graph.features
  std::vector<LineCandidate> lines;       // lookahead only: the cuts that split the part
};

// Inputs: part; options. Output: the part's state.
std::shared_ptr<const PartState> make_part_state(const Part& part, const PartStateOptions& options);

// Inputs:  state, with its graph; vertex_features, one per model vertex (graph.vertex_nodes order);
//          scale, the part's.
// Effect:  the lookahead node features (kLookaheadFeatures per node, above): the graph's one-hot kind,
//          the vertex's summary at model-vertex nodes (zero elsewhere), the scale at every node.
//          Shared by grid parts and general regions (region_state.h).
void set_lookahead_features(PartState& state, const std::vector<std::array<float, kVertexLookahead>>& vertex_features,
                            const std::array<float, kPartScale>& scale);

// Inputs:  state, of a part P; symmetry in 0..7 (part_symmetry.h: bit 0 mirrors x, bits 1-2 count
//          quarter turns).
// Outputs: what the value network reads of transform_part(P, symmetry), made from state without a
//          second triangulation: the same nodes, node kinds and edges; positions and
//          pseudo-coordinates transformed; with lookahead features, a quarter turn swaps the
//          horizontal and vertical cut summaries. With the bounded graph method this equals
//          make_part_state(transform_part(P, symmetry)) up to the order of the nodes and the
//          triangulation's choice of diagonal among cocircular points. Observations and
//          candidate cuts are left empty (the value network does not read them).
std::shared_ptr<const PartState> symmetric_view(const PartState& state, int symmetry);

}  // namespace autoblock
