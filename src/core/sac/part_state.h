// What the agent sees of a part: its graph (for the value network) and the local observation at
// every model vertex (for the actor and critics), in Episode::current_vertices order.
#pragma once

#include <memory>
#include <vector>

#include "core/env/observation.h"
#include "core/geometry/part.h"
#include "core/graph/part_graph.h"

namespace autoblock {

struct PartState {
  PartGraph graph;
  std::vector<Observation> observations;  // one per model vertex, graph.vertex_nodes order
};

// Inputs: part; options, the triangulation's. Output: the part's state.
std::shared_ptr<const PartState> make_part_state(const Part& part, const GraphOptions& options);

}  // namespace autoblock
