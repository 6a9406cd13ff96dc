#include "core/nn/spline_graph.h"

#include <torch/torch.h>

#include <stdexcept>

#include "core/nn/spline_basis.h"

namespace autoblock {

SplineGraph spline_graph(const torch::Tensor& edge_index, const torch::Tensor& pseudo, int64_t num_nodes,
                         int64_t kernel_size) {
  if (edge_index.dim() != 2 || edge_index.size(0) != 2 || edge_index.scalar_type() != torch::kLong) {
    throw std::invalid_argument("spline_graph: edge_index must be an int64 [2,E] tensor");
  }
  if (pseudo.dim() != 2 || pseudo.size(0) != edge_index.size(1)) {
    throw std::invalid_argument("spline_graph: pseudo must be [E,2] with E the number of edges");
  }
  if (num_nodes < 1) throw std::invalid_argument("spline_graph: num_nodes must be positive");
  const int64_t edges = edge_index.size(1);
  if (edges > 0 && (edge_index.min().item<int64_t>() < 0 || edge_index.max().item<int64_t>() >= num_nodes)) {
    throw std::invalid_argument("spline_graph: edge_index holds a node index outside [0, num_nodes)");
  }
  torch::NoGradGuard no_grad;
  const int64_t kk = kernel_size * kernel_size;
  const auto [basis, weight_index] = spline_basis(pseudo.detach(), kernel_size);  // [E,4] each
  const torch::Tensor source = edge_index[0];
  const torch::Tensor target = edge_index[1];
  const torch::Tensor degree =
      torch::zeros({num_nodes}, pseudo.options()).index_add_(0, target, torch::ones({edges}, pseudo.options()));
  const torch::Tensor scale = degree.clamp_min(1.0).reciprocal().index_select(0, target);  // [E]
  const torch::Tensor rows = (target.unsqueeze(1) * kk + weight_index).reshape({-1});
  const torch::Tensor columns = source.unsqueeze(1).expand({edges, kSplineProducts}).reshape({-1});
  const torch::Tensor values = (basis * scale.unsqueeze(1)).reshape({-1});
  SplineGraph graph;
  graph.mean_operator =
      torch::sparse_coo_tensor(torch::stack({rows, columns}), values, {num_nodes * kk, num_nodes}).coalesce();
  graph.num_nodes = num_nodes;
  graph.kernel_size = kernel_size;
  return graph;
}

}  // namespace autoblock
