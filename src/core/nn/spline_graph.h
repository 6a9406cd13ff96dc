// The part of a spline convolution that depends only on the graph, built once per graph and
// shared by every SplineConv layer that runs on it.
//
// For a graph with N nodes and kernel size K, the mean aggregation of SplineConv's messages is
//   out[t] = 1/deg(t) sum_{edges e: s -> t} sum_p basis[e,p] x[s] W[weight_index[e,p]]
//          = sum_k (A_k x)[t] W_k,   A_k[t,s] = sum over those (e,p) with weight_index k of basis[e,p] / deg(t),
// so stacking the K*K sparse matrices A_k row-interleaved gives one sparse operator
// M [N*K*K, N] (row t*K*K + k is A_k[t,:]) and the layer becomes one sparse product M x, viewed as
// [N, K*K*in], and one dense product with the weight viewed as [K*K*in, out].
#pragma once

#include <torch/types.h>

#include <cstdint>

namespace autoblock {

struct SplineGraph {
  torch::Tensor mean_operator;  // sparse COO [N*K*K, N], coalesced, pseudo's dtype; no gradient
  int64_t num_nodes = 0;        // N
  int64_t kernel_size = 0;      // K
};

// Inputs:  edge_index [2,E] int64 (row 0 source, row 1 target, indices < num_nodes); pseudo [E,2]
//          in [0,1] (float or double); num_nodes N >= 1; kernel_size K >= 2.
// Outputs: the graph's mean-aggregation operator (see above). Nodes without incoming edges have
//          empty rows (their aggregate is 0). Pseudo is treated as data: no gradient flows to it.
// Throws std::invalid_argument for inconsistent shapes or out-of-range indices.
SplineGraph spline_graph(const torch::Tensor& edge_index, const torch::Tensor& pseudo, int64_t num_nodes,
                         int64_t kernel_size);

}  // namespace autoblock
