// The open B-spline basis of degree 1 in 2-D that weights SplineConv's kernels (Fey et al. 2018),
// computed as pytorch_spline_conv does.
#pragma once

#include <torch/types.h>

#include <cstdint>
#include <utility>

namespace autoblock {

// Number of (basis, weight index) products per edge: (degree + 1)^dimensions = 2^2.
constexpr int64_t kSplineProducts = 4;

// Open B-spline basis of degree 1 in 2-D, as pytorch_spline_conv: v_d = pseudo_d * (K - 1); for
// each of the 4 (=2x2) products s, k_mod_d = bit d of s, weight index =
// sum_d ((floor(v_d) + k_mod_d) % K) * K^d (dimension 0 fastest),
// basis = prod_d (k_mod_d ? frac(v_d) : 1 - frac(v_d)).
// Inputs:  pseudo [E,2] float (or double) in [0,1]; kernel_size K >= 2.
// Outputs: basis [E,4] of pseudo's dtype, weight_index [E,4] int64 in [0, K*K).
//          Differentiable with respect to pseudo almost everywhere (plain tensor operations).
// Throws std::invalid_argument for a pseudo that is not [E,2] floating point or K < 2.
std::pair<torch::Tensor, torch::Tensor> spline_basis(const torch::Tensor& pseudo, int64_t kernel_size);

}  // namespace autoblock
