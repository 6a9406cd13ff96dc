// Several part graphs as one disjoint graph, the form the value network takes.
#pragma once

#include <torch/types.h>

#include <cstdint>
#include <vector>

#include "core/graph/part_graph.h"

namespace autoblock {

struct GraphBatch {
  torch::Tensor x;             // [N,3] float, graphs concatenated
  torch::Tensor edge_index;    // [2,E] int64, node indices offset per graph
  torch::Tensor pseudo;        // [E,2] float
  torch::Tensor vertex_nodes;  // [V] int64: global node index of every model vertex, graph by graph
  std::vector<int64_t> vertex_offsets;  // size graphs+1: graph g's vertices are vertex_nodes[offsets[g]:offsets[g+1]]
  std::vector<int64_t> node_offsets;    // size graphs+1: graph g's nodes are [node_offsets[g], node_offsets[g+1])

  int64_t graph_count() const { return static_cast<int64_t>(node_offsets.size()) - 1; }
  int64_t node_count() const { return node_offsets.empty() ? 0 : node_offsets.back(); }
};

// Inputs:  graphs (at least one, none null), e.g. part_graph results.
// Outputs: them as one graph: nodes, edges and vertices in the given order, each graph's node
//          indices shifted by the nodes before it; pseudo-coordinates kept per graph (each graph
//          stays normalised by its own largest edge component).
// Throws std::invalid_argument for an empty list or a null pointer.
GraphBatch batch_graphs(const std::vector<const PartGraph*>& graphs);

}  // namespace autoblock
