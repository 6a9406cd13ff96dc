#include "core/nn/spline_basis.h"

#include <torch/torch.h>

#include <stdexcept>

namespace autoblock {

std::pair<torch::Tensor, torch::Tensor> spline_basis(const torch::Tensor& pseudo, int64_t kernel_size) {
  if (pseudo.dim() != 2 || pseudo.size(1) != 2 || !pseudo.is_floating_point()) {
    throw std::invalid_argument("spline_basis: pseudo must be a floating point [E,2] tensor");
  }
  if (kernel_size < 2) throw std::invalid_argument("spline_basis: kernel_size must be at least 2");
  const torch::Tensor v = pseudo * static_cast<double>(kernel_size - 1);
  const torch::Tensor lower = v.floor();
  const torch::Tensor frac = v - lower;                // [E,2]
  const torch::Tensor cell = lower.to(torch::kLong);   // [E,2], floor(v_d)
  // Dimension d of product s uses the upper knot when bit d of s is set.
  const torch::Tensor bits = torch::tensor({0, 1, 0, 1, 0, 0, 1, 1}, torch::kLong).view({2, kSplineProducts});
  std::vector<torch::Tensor> factor(2), index(2);
  for (int64_t d = 0; d < 2; ++d) {
    const torch::Tensor k_mod = bits[d].unsqueeze(0);                            // [1,4]
    const torch::Tensor f = frac.select(1, d).unsqueeze(1);                     // [E,1]
    factor[static_cast<size_t>(d)] = torch::where(k_mod.to(torch::kBool), f, 1.0 - f);  // [E,4]
    index[static_cast<size_t>(d)] = (cell.select(1, d).unsqueeze(1) + k_mod).remainder(kernel_size);
  }
  torch::Tensor basis = factor[0] * factor[1];
  torch::Tensor weight_index = index[0] + index[1] * kernel_size;
  return {basis, weight_index};
}

}  // namespace autoblock
