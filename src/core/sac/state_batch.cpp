#include "core/sac/state_batch.h"

#include <torch/torch.h>

#include <cstring>
#include <stdexcept>

namespace autoblock {

GraphBatch batch_states(const std::vector<const PartState*>& states) {
  std::vector<const PartGraph*> graphs;
  for (const PartState* s : states) graphs.push_back(&s->graph);
  GraphBatch batch = batch_graphs(graphs);
  const int features = states.front()->feature_count;
  if (features == 3 && states.front()->features.empty()) return batch;
  torch::Tensor x = torch::empty({batch.node_count(), features}, torch::kFloat);
  float* out = x.data_ptr<float>();
  for (const PartState* s : states) {
    if (s->feature_count != features || s->features.size() != s->graph.positions.size() * static_cast<size_t>(features)) {
      throw std::logic_error("batch_states: states with different node features");
    }
    std::memcpy(out, s->features.data(), s->features.size() * sizeof(float));
    out += s->features.size();
  }
  batch.x = x;
  return batch;
}

}  // namespace autoblock
