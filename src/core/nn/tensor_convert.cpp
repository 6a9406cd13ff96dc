#include "core/nn/tensor_convert.h"

#include <torch/torch.h>

#include <algorithm>

namespace autoblock {

GraphBatch graph_batch_of(const PartGraph& graph) { return batch_graphs({&graph}); }

torch::Tensor observations_tensor(const std::vector<Observation>& observations) {
  const auto rows = static_cast<int64_t>(observations.size());
  torch::Tensor out = torch::empty({rows, kObservationSize}, torch::kFloat);
  float* data = out.data_ptr<float>();
  for (const Observation& o : observations) data = std::copy(o.begin(), o.end(), data);
  return out;
}

torch::Tensor vertex_values(const torch::Tensor& node_values, const GraphBatch& batch) {
  return node_values.index_select(0, batch.vertex_nodes);
}

}  // namespace autoblock
