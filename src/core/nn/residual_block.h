// The value network's residual block (paper, "Network Architecture"): two SplineConvs with batch
// norm, ELU between them, and a skip path that is the identity when the width stays and a
// SplineConv with batch norm when it changes; ELU after the sum.
#pragma once

#include <torch/nn/module.h>
#include <torch/nn/modules/batchnorm.h>
#include <torch/nn/pimpl.h>
#include <torch/types.h>

#include <cstdint>

#include "core/nn/spline_conv.h"
#include "core/nn/spline_graph.h"

namespace autoblock {

struct ResidualBlockImpl : torch::nn::Module {
  // Inputs: in and out widths (>= 1), kernel size K.
  ResidualBlockImpl(int64_t in_channels, int64_t out_channels, int64_t kernel_size);

  // Inputs: x [N,in]; graph, x's graph operator. Output: [N,out] =
  // ELU(BN(conv2(ELU(BN(conv1(x))))) + skip(x)), skip = BN(conv_skip(x)) or x.
  torch::Tensor forward(const torch::Tensor& x, const SplineGraph& graph);

  SplineConv conv1{nullptr}, conv2{nullptr}, skip_conv{nullptr};  // skip_conv empty when in == out
  torch::nn::BatchNorm1d bn1{nullptr}, bn2{nullptr}, skip_bn{nullptr};
};
TORCH_MODULE(ResidualBlock);

}  // namespace autoblock
