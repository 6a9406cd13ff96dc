#include "core/nn/spline_conv.h"

#include <torch/torch.h>

#include <cmath>
#include <stdexcept>

#include "core/nn/spline_weighting.h"

namespace autoblock {

SplineConvImpl::SplineConvImpl(int64_t in_channels_, int64_t out_channels_, int64_t kernel_size_)
    : in_channels(in_channels_), out_channels(out_channels_), kernel_size(kernel_size_) {
  if (in_channels < 1 || out_channels < 1 || kernel_size < 2) {
    throw std::invalid_argument("SplineConv: channels must be >= 1 and kernel_size >= 2");
  }
  weight = register_parameter("weight", torch::empty({kernel_size * kernel_size, in_channels, out_channels}));
  root = register_parameter("root", torch::empty({in_channels, out_channels}));
  bias = register_parameter("bias", torch::empty({out_channels}));
  reset_parameters();
}

void SplineConvImpl::reset_parameters() {
  torch::NoGradGuard no_grad;
  const double bound = 1.0 / std::sqrt(static_cast<double>(in_channels));
  weight.uniform_(-bound, bound);
  root.uniform_(-bound, bound);
  bias.zero_();
}

torch::Tensor SplineConvImpl::forward(const torch::Tensor& x, const torch::Tensor& edge_index,
                                      const torch::Tensor& pseudo) {
  return forward_on(x, spline_graph(edge_index, pseudo, x.size(0), kernel_size));
}

torch::Tensor SplineConvImpl::forward_on(const torch::Tensor& x, const SplineGraph& graph) {
  if (x.dim() != 2 || x.size(1) != in_channels) {
    throw std::invalid_argument("SplineConv: x must be [N," + std::to_string(in_channels) + "]");
  }
  if (graph.kernel_size != kernel_size) {
    throw std::invalid_argument("SplineConv: the graph operator was built for another kernel size");
  }
  return spline_mean_weighting(x, weight, graph) + torch::addmm(bias, x, root);
}

}  // namespace autoblock
