#include "core/nn/spline_weighting.h"

#include <torch/torch.h>

#include <cblas.h>

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

namespace {

// spline_mean_weighting without gradients, by cells (SplineCellRows, spline_graph.h): the compact
// rows of M x, each cell's rows times that cell's [in, out] matrix (one BLAS product per cell), the
// products added at their nodes. The same sums as the dense form but over the nonzero blocks only.
torch::Tensor cell_weighting(const torch::Tensor& x_in, const torch::Tensor& weight_in, const SplineCellRows& cells,
                             int64_t n) {
  const torch::Tensor x = x_in.contiguous();
  const torch::Tensor weight = weight_in.contiguous();
  const int64_t in = x.size(1), out = weight.size(2);
  const int64_t rows = static_cast<int64_t>(cells.targets.size());
  const float* xs = x.data_ptr<float>();
  const float* w = weight.data_ptr<float>();
  std::vector<float> gathered(static_cast<size_t>(rows * in), 0.0f), products(static_cast<size_t>(rows * out));
  for (int64_t p = 0; p < rows; ++p) {
    float* g = gathered.data() + p * in;
    for (int64_t e = cells.row_start[static_cast<size_t>(p)]; e < cells.row_start[static_cast<size_t>(p + 1)]; ++e) {
      const float a = cells.values[static_cast<size_t>(e)];
      const float* source = xs + cells.columns[static_cast<size_t>(e)] * in;
      for (int64_t j = 0; j < in; ++j) g[j] += a * source[j];
    }
  }
  for (size_t k = 0; k + 1 < cells.cell_start.size(); ++k) {
    const int64_t begin = cells.cell_start[k], m = cells.cell_start[k + 1] - begin;
    if (m == 0) continue;
    cblas_sgemm(CblasRowMajor, CblasNoTrans, CblasNoTrans, static_cast<int>(m), static_cast<int>(out),
                static_cast<int>(in), 1.0f, gathered.data() + begin * in, static_cast<int>(in),
                w + static_cast<int64_t>(k) * in * out, static_cast<int>(out), 0.0f, products.data() + begin * out,
                static_cast<int>(out));
  }
  torch::Tensor result = torch::zeros({n, out}, x.options());
  float* r = result.data_ptr<float>();
  for (int64_t p = 0; p < rows; ++p) {
    float* target = r + cells.targets[static_cast<size_t>(p)] * out;
    const float* product = products.data() + p * out;
    for (int64_t j = 0; j < out; ++j) target[j] += product[j];
  }
  return result;
}

}  // namespace

torch::Tensor spline_mean_weighting(const torch::Tensor& x, const torch::Tensor& weight, const SplineGraph& graph) {
  const int64_t kk = graph.kernel_size * graph.kernel_size;
  if (x.dim() != 2 || x.size(0) != graph.num_nodes) {
    throw std::invalid_argument("spline_mean_weighting: x must be [N,in] with N the graph's node count");
  }
  if (weight.dim() != 3 || weight.size(0) != kk || weight.size(1) != x.size(1)) {
    throw std::invalid_argument("spline_mean_weighting: weight must be [K*K,in,out] with the graph's K");
  }
  const int64_t n = x.size(0), in = x.size(1), out = weight.size(2);
  if (graph.cell_rows && !torch::GradMode::is_enabled() && x.scalar_type() == torch::kFloat &&
      weight.scalar_type() == torch::kFloat && x.device().is_cpu()) {
    return cell_weighting(x, weight, *graph.cell_rows, n);
  }
  if (!graph.mean_operator.defined()) {
    throw std::invalid_argument(
        "spline_mean_weighting: the graph was built without gradients, for float inputs without gradients only");
  }
  const torch::Tensor& op = graph.mean_operator;
  const torch::Tensor gathered = torch::mm(op.scalar_type() == x.scalar_type() ? op : op.to(x.scalar_type()), x);
  return gathered.view({n, kk * in}).mm(weight.reshape({kk * in, out}));
}

}  // namespace autoblock
