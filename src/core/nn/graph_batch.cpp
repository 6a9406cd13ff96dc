#include "core/nn/graph_batch.h"

#include <torch/torch.h>

#include <stdexcept>

namespace autoblock {

GraphBatch batch_graphs(const std::vector<const PartGraph*>& graphs) {
  if (graphs.empty()) throw std::invalid_argument("batch_graphs: no graphs");
  GraphBatch batch;
  batch.node_offsets.push_back(0);
  batch.vertex_offsets.push_back(0);
  int64_t edges = 0;
  for (const PartGraph* graph : graphs) {
    if (!graph) throw std::invalid_argument("batch_graphs: null graph");
    batch.node_offsets.push_back(batch.node_offsets.back() + graph->node_count());
    batch.vertex_offsets.push_back(batch.vertex_offsets.back() + static_cast<int64_t>(graph->vertex_nodes.size()));
    edges += graph->edge_count();
  }
  const int64_t nodes = batch.node_offsets.back(), vertices = batch.vertex_offsets.back();
  batch.x = torch::empty({nodes, 3}, torch::kFloat);
  batch.edge_index = torch::empty({2, edges}, torch::kLong);
  batch.pseudo = torch::empty({edges, 2}, torch::kFloat);
  batch.vertex_nodes = torch::empty({vertices}, torch::kLong);
  float* x = batch.x.data_ptr<float>();
  int64_t* source = batch.edge_index.data_ptr<int64_t>();
  int64_t* target = source + edges;
  float* pseudo = batch.pseudo.data_ptr<float>();
  int64_t* vertex = batch.vertex_nodes.data_ptr<int64_t>();
  for (size_t g = 0; g < graphs.size(); ++g) {
    const PartGraph& graph = *graphs[g];
    const int64_t offset = batch.node_offsets[g];
    for (const auto& f : graph.features) {
      for (float value : f) *x++ = value;
    }
    for (size_t e = 0; e < graph.edges.size(); ++e) {
      *source++ = offset + graph.edges[e][0];
      *target++ = offset + graph.edges[e][1];
      *pseudo++ = graph.pseudo[e][0];
      *pseudo++ = graph.pseudo[e][1];
    }
    for (int v : graph.vertex_nodes) *vertex++ = offset + v;
  }
  return batch;
}

}  // namespace autoblock
