// Several part states as one graph batch for the value network, with their node features.
#pragma once

#include <vector>

#include "core/nn/graph_batch.h"
#include "core/sac/part_state.h"

namespace autoblock {

// Inputs: states (at least one, all with the same feature_count). Output: the batch; x holds the
// states' node features.
GraphBatch batch_states(const std::vector<const PartState*>& states);

}  // namespace autoblock
