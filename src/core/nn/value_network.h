// The value network of the paper ("Value Network", "Network Architecture"): a SplineCNN graph
// network over a part's triangulation (graph/part_graph.h) giving one value per node; the agent
// reads it at the model-vertex nodes. Widths and depth are configurable; "paper" is the paper's.
#pragma once

#include <torch/nn/module.h>
#include <torch/nn/modules/batchnorm.h>
#include <torch/nn/modules/container/modulelist.h>
#include <torch/nn/pimpl.h>
#include <torch/types.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/nn/spline_conv.h"
#include "core/nn/spline_graph.h"

namespace autoblock {

struct ValueNetworkConfig {
  std::string name;
  int64_t first_width = 64;
  std::vector<int64_t> block_widths;  // one residual block per entry
  int64_t kernel_size = 5;
  int64_t inputs = 3;   // features per node: the one-hot node kinds (part_graph.h), plus any extras
  int64_t outputs = 1;  // values per node: 1 (the paper's), or e.g. 2 (one per cut direction)

  static ValueNetworkConfig paper();  // "paper": 64; 128, 256, 128, 64, 32, 16, 8
  static ValueNetworkConfig small();  // "small": 32; 64, 32, 16 (about 1/18 of paper's work per node)
  // Inputs: "paper" or "small". Throws InputError (core/common/error.h) for unknown names.
  static ValueNetworkConfig by_name(const std::string& name);
  // The preset names, in that order.
  static std::vector<std::string> names();
};

// The paper's GNN: SplineConv(3 -> first) + BatchNorm + ELU; residual blocks (SplineConv, BN,
// ELU, SplineConv, BN; skip path a SplineConv + BN when the width changes, identity otherwise; ELU
// after the sum); output SplineConv(last -> outputs, 1 in the paper), no BN, no activation. Batch norm normalises over
// all nodes of the (batched) input, as PyG's BatchNorm does.
struct ValueNetworkImpl : torch::nn::Module {
  // Throws InputError for a config with a width < 1 or kernel_size < 2.
  explicit ValueNetworkImpl(const ValueNetworkConfig& config);

  // x [N,3] node features, edge_index [2,E] int64, pseudo [E,2] -> [N] one value per node
  // ([N, outputs] when config.outputs > 1).
  torch::Tensor forward(const torch::Tensor& x, const torch::Tensor& edge_index, const torch::Tensor& pseudo);
  // The same with the graph's operator built beforehand (spline_graph(edge_index, pseudo, N,
  // config.kernel_size)), e.g. kept with a stored graph and reused. (Not an overload of forward:
  // ModuleHolder's operator() needs forward to be unique.)
  torch::Tensor forward_on(const torch::Tensor& x, const SplineGraph& graph);

  ValueNetworkConfig config;
  SplineConv input_conv{nullptr}, output_conv{nullptr};
  torch::nn::BatchNorm1d input_bn{nullptr};
  torch::nn::ModuleList blocks{nullptr};  // ResidualBlock (residual_block.h)
};
TORCH_MODULE(ValueNetwork);

}  // namespace autoblock
