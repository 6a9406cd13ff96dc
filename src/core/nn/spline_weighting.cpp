#include "core/nn/spline_weighting.h"

#include <torch/torch.h>

#include <stdexcept>

#include "core/nn/spline_basis.h"

namespace autoblock {

torch::Tensor spline_weighting(const torch::Tensor& x, const torch::Tensor& source, const torch::Tensor& weight,
                               const torch::Tensor& basis, const torch::Tensor& weight_index) {
  if (x.dim() != 2 || weight.dim() != 3 || weight.size(1) != x.size(1)) {
    throw std::invalid_argument("spline_weighting: x must be [N,in] and weight [K*K,in,out]");
  }
  const int64_t n = x.size(0), kk = weight.size(0), out = weight.size(2), edges = source.size(0);
  if (basis.sizes() != torch::IntArrayRef{edges, kSplineProducts} || weight_index.sizes() != basis.sizes()) {
    throw std::invalid_argument("spline_weighting: basis and weight_index must be [E,4]");
  }
  // Every node's features through every kernel: [K*K, N, out], flattened to rows k*N + node.
  const torch::Tensor all = torch::matmul(x.unsqueeze(0), weight).reshape({kk * n, out});
  const torch::Tensor rows = (weight_index * n + source.unsqueeze(1)).reshape({-1});
  return (all.index_select(0, rows).view({edges, kSplineProducts, out}) * basis.unsqueeze(2)).sum(1);
}

torch::Tensor spline_mean_weighting(const torch::Tensor& x, const torch::Tensor& weight, const SplineGraph& graph) {
  const int64_t kk = graph.kernel_size * graph.kernel_size;
  if (x.dim() != 2 || x.size(0) != graph.num_nodes) {
    throw std::invalid_argument("spline_mean_weighting: x must be [N,in] with N the graph's node count");
  }
  if (weight.dim() != 3 || weight.size(0) != kk || weight.size(1) != x.size(1)) {
    throw std::invalid_argument("spline_mean_weighting: weight must be [K*K,in,out] with the graph's K");
  }
  const int64_t n = x.size(0), in = x.size(1), out = weight.size(2);
  const torch::Tensor& op = graph.mean_operator;
  const torch::Tensor gathered = torch::mm(op.scalar_type() == x.scalar_type() ? op : op.to(x.scalar_type()), x);
  return gathered.view({n, kk * in}).mm(weight.reshape({kk * in, out}));
}

}  // namespace autoblock
