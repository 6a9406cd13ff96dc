// Where a deployed learned policy spends its time, for the benchmarks: the calling thread's running
// totals of graph building, lookahead (the candidate cuts and their features), the value network's
// forward passes (batching included) and the graphs' sizes. Thread-local, so policies on several
// threads do not mix; the cost is a few clock reads per part and per step.
#pragma once

#include <vector>

namespace autoblock {

struct DeployProfile {
  double graph_seconds = 0.0;      // part_graph
  double lookahead_seconds = 0.0;  // look_ahead and the node features (make_part_state less the graph)
  double forward_seconds = 0.0;    // batching the graphs and the network's forward pass
  long states = 0;                 // part states built (graph + lookahead)
  long forwards = 0;               // forward passes (batches)
  long graphs_evaluated = 0;       // graphs through the network (batch members)
  long values_reused = 0;          // piece values taken from the policy's cache instead of the network
  long proposals = 0;              // general faces: the actor's proposals made (cut_proposer.h)
  long proposals_progress = 0;     // of them, those that made progress (candidates)
  long proposals_chosen = 0;       // of them, those the policy took
  std::vector<int> graph_nodes;    // node count of every graph built (the first 4 M)
};

// Outputs: the calling thread's profile (zero at thread start; reset it with `= {}`).
DeployProfile& deploy_profile();

}  // namespace autoblock
