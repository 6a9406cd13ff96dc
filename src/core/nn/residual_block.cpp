#include "core/nn/residual_block.h"

#include <torch/torch.h>

namespace autoblock {

ResidualBlockImpl::ResidualBlockImpl(int64_t in_channels, int64_t out_channels, int64_t kernel_size) {
  conv1 = register_module("conv1", SplineConv(in_channels, out_channels, kernel_size));
  bn1 = register_module("bn1", torch::nn::BatchNorm1d(out_channels));
  conv2 = register_module("conv2", SplineConv(out_channels, out_channels, kernel_size));
  bn2 = register_module("bn2", torch::nn::BatchNorm1d(out_channels));
  if (in_channels != out_channels) {
    skip_conv = register_module("skip_conv", SplineConv(in_channels, out_channels, kernel_size));
    skip_bn = register_module("skip_bn", torch::nn::BatchNorm1d(out_channels));
  }
}

torch::Tensor ResidualBlockImpl::forward(const torch::Tensor& x, const SplineGraph& graph) {
  torch::Tensor h = torch::elu(bn1(conv1->forward_on(x, graph)));
  h = bn2(conv2->forward_on(h, graph));
  const torch::Tensor skip = skip_conv ? skip_bn(skip_conv->forward_on(x, graph)) : x;
  return torch::elu(h + skip);
}

}  // namespace autoblock
