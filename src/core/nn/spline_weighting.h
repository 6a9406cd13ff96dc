// SplineConv's weighting kernel: the messages x[source] @ W(pseudo), where W(pseudo) is the
// B-spline interpolation of the K*K kernel matrices (spline_basis.h).
//
// Two forms of the same arithmetic, both a few dense products and no loop over edges:
// spline_weighting gives every edge's message (pytorch_spline_conv's kernel of that name);
// spline_mean_weighting gives each node's mean incoming message directly through the graph's
// operator (spline_graph.h), which is what SplineConv uses: it never materialises the per-edge
// messages and is the faster of the two (see the report of bench_value_network).
#pragma once

#include <torch/types.h>

#include "core/nn/spline_graph.h"

namespace autoblock {

// Inputs:  x [N,in] node features; source [E] int64 (each edge's source node); weight [K*K,in,out];
//          basis [E,4] and weight_index [E,4] from spline_basis.
// Outputs: messages [E,out]: row e = sum_s basis[e,s] * (x[source[e]] @ weight[weight_index[e,s]]),
//          computed as x @ weight for all K*K kernels at once, then a gather. Differentiable with
//          respect to x, weight and basis.
torch::Tensor spline_weighting(const torch::Tensor& x, const torch::Tensor& source, const torch::Tensor& weight,
                               const torch::Tensor& basis, const torch::Tensor& weight_index);

// Inputs:  x [N,in]; weight [K*K,in,out]; graph, the operator of x's graph (N nodes, same K).
// Outputs: [N,out], at every node the mean of its incoming messages (0 at a node without incoming
//          edges): (M x) viewed [N, K*K*in], times weight viewed [K*K*in, out]. Differentiable with
//          respect to x and weight. With gradients off and the graph's cell rows built (float
//          tensors), the same sums over the nonzero (node, cell) blocks only: one product per cell
//          (spline_graph.h), about a quarter of the work on part graphs.
// Throws std::invalid_argument when the shapes do not fit together.
torch::Tensor spline_mean_weighting(const torch::Tensor& x, const torch::Tensor& weight, const SplineGraph& graph);

}  // namespace autoblock
