// SplineConv (Fey et al. 2018) with an open B-spline kernel of degree 1 on 2-D pseudo-coordinates,
// mean aggregation, a root weight and a bias: PyG's SplineConv(in, out, dim=2, kernel_size=K,
// degree=1, aggr="mean").
#pragma once

#include <torch/nn/module.h>
#include <torch/nn/pimpl.h>
#include <torch/types.h>

#include <cstdint>

#include "core/nn/spline_graph.h"

namespace autoblock {

struct SplineConvImpl : torch::nn::Module {
  // Inputs: channel counts (>= 1); kernel_size K >= 2 per dimension (K*K kernel matrices).
  // Parameters start uniform in +-1/sqrt(in_channels) (weight, root); the bias starts at 0.
  // Throws std::invalid_argument for bad sizes.
  SplineConvImpl(int64_t in_channels, int64_t out_channels, int64_t kernel_size = 5);

  // x [N,in], edge_index [2,E] int64 (row 0 source, row 1 target), pseudo [E,2] -> [N,out]:
  // mean over each node's incoming messages (0 when none) + x @ root + bias.
  torch::Tensor forward(const torch::Tensor& x, const torch::Tensor& edge_index, const torch::Tensor& pseudo);
  // The same with the graph's operator built beforehand (spline_graph.h), for networks that run
  // several layers on one graph. (Not an overload of forward: ModuleHolder's operator() needs
  // forward to be unique.)
  torch::Tensor forward_on(const torch::Tensor& x, const SplineGraph& graph);

  void reset_parameters();

  int64_t in_channels = 0, out_channels = 0, kernel_size = 0;
  torch::Tensor weight, root, bias;  // [K*K, in, out], [in, out], [out]
};
TORCH_MODULE(SplineConv);

}  // namespace autoblock
