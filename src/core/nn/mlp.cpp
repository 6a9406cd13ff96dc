#include "core/nn/mlp.h"

#include <torch/torch.h>

#include <stdexcept>
#include <string>

namespace autoblock {

MlpImpl::MlpImpl(int64_t in, std::vector<int64_t> hidden, int64_t out, bool relu_output_) : relu_output(relu_output_) {
  std::vector<int64_t> sizes{in};
  sizes.insert(sizes.end(), hidden.begin(), hidden.end());
  sizes.push_back(out);
  for (int64_t size : sizes) {
    if (size < 1) throw std::invalid_argument("Mlp: layer sizes must be >= 1");
  }
  for (size_t k = 0; k + 1 < sizes.size(); ++k) {
    layers.push_back(register_module("linear" + std::to_string(k), torch::nn::Linear(sizes[k], sizes[k + 1])));
  }
}

torch::Tensor MlpImpl::forward(const torch::Tensor& x) {
  torch::Tensor h = x;
  for (size_t k = 0; k < layers.size(); ++k) {
    h = layers[k](h);
    if (k + 1 < layers.size() || relu_output) h = torch::relu(h);
  }
  return h;
}

}  // namespace autoblock
