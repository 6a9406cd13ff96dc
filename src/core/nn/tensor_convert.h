// Plain data to tensors: one part graph as a batch, and local observations as a matrix.
#pragma once

#include <torch/types.h>

#include <vector>

#include "core/env/observation.h"
#include "core/graph/part_graph.h"
#include "core/nn/graph_batch.h"

namespace autoblock {

// Inputs: graph. Output: the batch of that one graph (batch_graphs({&graph})).
GraphBatch graph_batch_of(const PartGraph& graph);

// Inputs: observations (B of them, B may be 0). Output: [B,9] float, one row per observation.
torch::Tensor observations_tensor(const std::vector<Observation>& observations);

// Inputs: node_values [N] (a value network's output on batch); batch. Output: [V] the values at the
//         model-vertex nodes, graph by graph (rows vertex_offsets[g] .. vertex_offsets[g+1] are
//         graph g's vertices in part_boundary order). Differentiable.
torch::Tensor vertex_values(const torch::Tensor& node_values, const GraphBatch& batch);

}  // namespace autoblock
