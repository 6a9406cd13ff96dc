// A fully connected network: the paper's actor and critics (9 -> 256 -> 128 -> 64 -> 2).
#pragma once

#include <torch/nn/module.h>
#include <torch/nn/modules/linear.h>
#include <torch/nn/pimpl.h>
#include <torch/types.h>

#include <cstdint>
#include <vector>

namespace autoblock {

// Fully connected in -> hidden... -> out with ReLU after every hidden layer, and after the output
// layer too when relu_output. Layers are registered as "linear0", "linear1", ... (LibTorch's
// default Linear initialisation).
struct MlpImpl : torch::nn::Module {
  // Inputs: sizes >= 1 (hidden may be empty: one linear layer). Throws std::invalid_argument.
  MlpImpl(int64_t in, std::vector<int64_t> hidden, int64_t out, bool relu_output);

  // x [B,in] (or [in]) -> [B,out] (or [out]).
  torch::Tensor forward(const torch::Tensor& x);

  std::vector<torch::nn::Linear> layers;
  bool relu_output = false;
};
TORCH_MODULE(Mlp);

}  // namespace autoblock
