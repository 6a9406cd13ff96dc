#include "core/nn/value_network.h"

#include <torch/torch.h>

#include "core/common/error.h"
#include "core/nn/residual_block.h"

namespace autoblock {

ValueNetworkConfig ValueNetworkConfig::paper() { return {"paper", 64, {128, 256, 128, 64, 32, 16, 8}, 5}; }

ValueNetworkConfig ValueNetworkConfig::small() { return {"small", 32, {64, 32, 16}, 5}; }

std::vector<std::string> ValueNetworkConfig::names() { return {"paper", "small"}; }

ValueNetworkConfig ValueNetworkConfig::by_name(const std::string& name) {
  if (name == "paper") return paper();
  if (name == "small") return small();
  throw InputError("unknown value network '" + name + "' (known: paper, small)");
}

ValueNetworkImpl::ValueNetworkImpl(const ValueNetworkConfig& config_) : config(config_) {
  if (config.first_width < 1 || config.kernel_size < 2 || config.inputs < 1 || config.outputs < 1) {
    throw InputError("value network '" + config.name + "': widths must be >= 1 and the kernel size >= 2");
  }
  for (int64_t width : config.block_widths) {
    if (width < 1) throw InputError("value network '" + config.name + "': widths must be >= 1");
  }
  const int64_t k = config.kernel_size;
  input_conv = register_module("input_conv", SplineConv(config.inputs, config.first_width, k));
  input_bn = register_module("input_bn", torch::nn::BatchNorm1d(config.first_width));
  blocks = register_module("blocks", torch::nn::ModuleList());
  int64_t width = config.first_width;
  for (int64_t next : config.block_widths) {
    blocks->push_back(ResidualBlock(width, next, k));
    width = next;
  }
  output_conv = register_module("output_conv", SplineConv(width, config.outputs, k));
}

torch::Tensor ValueNetworkImpl::forward(const torch::Tensor& x, const torch::Tensor& edge_index,
                                        const torch::Tensor& pseudo) {
  return forward_on(x, spline_graph(edge_index, pseudo, x.size(0), config.kernel_size));
}

torch::Tensor ValueNetworkImpl::forward_on(const torch::Tensor& x, const SplineGraph& graph) {
  torch::Tensor h = torch::elu(input_bn(input_conv->forward_on(x, graph)));
  for (const auto& block : *blocks) h = block->as<ResidualBlockImpl>()->forward(h, graph);
  const torch::Tensor out = output_conv->forward_on(h, graph);
  return config.outputs == 1 ? out.squeeze(1) : out;
}

}  // namespace autoblock
