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
#include <memory>
#include <vector>

namespace autoblock {

// For inference the same operator is kept in a second form that skips its empty rows: a node's
// incoming edges reach only a few of the K*K kernel cells (about a quarter of the (node, cell) pairs
// on part graphs), so (M x) has mostly zero [in]-blocks and its product with the weight wastes most
// of its work on them. The nonzero rows, ordered by cell and then node, with their entries (CSR), let
// spline_mean_weighting multiply each cell's rows by that cell's matrix alone (SplineCellRows).
struct SplineCellRows {
  std::vector<int64_t> row_start;  // P+1: entries of compact row p are [row_start[p], row_start[p+1])
  std::vector<int64_t> columns;    // source node of each entry
  std::vector<float> values;       // basis / deg(t) of each entry
  std::vector<int64_t> targets;    // P: the node t of compact row p
  std::vector<int64_t> cell_start; // K*K+1: compact rows of cell k are [cell_start[k], cell_start[k+1])
};

struct SplineGraph {
  // Sparse COO [N*K*K, N], coalesced, pseudo's dtype; no gradient. Not built (undefined) when
  // cell_rows is.
  torch::Tensor mean_operator;
  int64_t num_nodes = 0;        // N
  int64_t kernel_size = 0;      // K
  // Built instead of mean_operator when gradients are off at construction and pseudo is float
  // (deployment, the Bellman targets): the operator's nonzero rows by cell, straight from the edges.
  std::shared_ptr<const SplineCellRows> cell_rows;
};

// Inputs:  edge_index [2,E] int64 (row 0 source, row 1 target, indices < num_nodes); pseudo [E,2]
//          in [0,1] (float or double); num_nodes N >= 1; kernel_size K >= 2.
// Outputs: the graph's mean-aggregation operator (see above): as the sparse tensor mean_operator,
//          or, when gradients are off (torch::NoGradGuard) and pseudo is float, as its rows by cell
//          (cell_rows) only, which is what spline_mean_weighting uses then. Nodes without incoming
//          edges have empty rows (their aggregate is 0). Pseudo is treated as data: no gradient flows
//          to it.
// Throws std::invalid_argument for inconsistent shapes or out-of-range indices.
SplineGraph spline_graph(const torch::Tensor& edge_index, const torch::Tensor& pseudo, int64_t num_nodes,
                         int64_t kernel_size);

}  // namespace autoblock
