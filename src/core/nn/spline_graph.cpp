#include "core/nn/spline_graph.h"

#include <torch/torch.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/nn/spline_basis.h"

namespace autoblock {

namespace {

// The operator's entries straight from the edges, by cell (no tensor operations: this runs for every
// deployed forward pass). The same arithmetic as spline_basis and the tensor form below, in float:
// for edge s -> t and product p, cell k = i0 + i1 K from the pseudo-coordinates' knots, value
// basis / deg(t); entries with the same (k, t, s) summed, exact zeros (a knot hit exactly) left out.
SplineCellRows cell_rows_from_edges(const torch::Tensor& edge_index, const torch::Tensor& pseudo, int64_t num_nodes,
                                    int64_t kernel_size) {
  const torch::Tensor edges_c = edge_index.contiguous();
  const torch::Tensor pseudo_c = pseudo.detach().contiguous();
  const int64_t edges = edges_c.size(1), kk = kernel_size * kernel_size;
  const int64_t* source = edges_c.data_ptr<int64_t>();
  const int64_t* target = source + edges;
  const float* u = pseudo_c.data_ptr<float>();
  std::vector<float> degree(static_cast<size_t>(num_nodes), 0.0f);
  for (int64_t e = 0; e < edges; ++e) {
    if (source[e] < 0 || source[e] >= num_nodes || target[e] < 0 || target[e] >= num_nodes) {
      throw std::invalid_argument("spline_graph: edge_index holds a node index outside [0, num_nodes)");
    }
    degree[static_cast<size_t>(target[e])] += 1.0f;
  }
  struct Entry {
    int64_t row;  // k * N + t
    int64_t column;
    float value;
  };
  std::vector<Entry> entries;
  entries.reserve(static_cast<size_t>(edges * kSplineProducts));
  const float knots = static_cast<float>(kernel_size - 1);
  for (int64_t e = 0; e < edges; ++e) {
    float frac[2];
    int64_t cell[2];
    for (int d = 0; d < 2; ++d) {
      const float v = u[2 * e + d] * knots;
      const float lower = std::floor(v);
      frac[d] = v - lower;
      cell[d] = static_cast<int64_t>(lower);
    }
    const float scale = 1.0f / std::max(degree[static_cast<size_t>(target[e])], 1.0f);
    for (int p = 0; p < kSplineProducts; ++p) {
      const int bit0 = p & 1, bit1 = p >> 1;  // the upper knot in dimension 0 / 1 (spline_basis)
      const float basis = (bit0 ? frac[0] : 1.0f - frac[0]) * (bit1 ? frac[1] : 1.0f - frac[1]);
      const float value = basis * scale;
      if (value == 0.0f) continue;
      const int64_t i0 = ((cell[0] + bit0) % kernel_size + kernel_size) % kernel_size;
      const int64_t i1 = ((cell[1] + bit1) % kernel_size + kernel_size) % kernel_size;
      entries.push_back({(i0 + i1 * kernel_size) * num_nodes + target[e], source[e], value});
    }
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.row != b.row ? a.row < b.row : a.column < b.column; });
  SplineCellRows out;
  out.cell_start.assign(static_cast<size_t>(kk + 1), 0);
  out.row_start.push_back(0);
  for (size_t i = 0; i < entries.size(); ++i) {
    const Entry& entry = entries[i];
    const bool new_row = i == 0 || entry.row != entries[i - 1].row;
    if (!new_row && entry.column == entries[i - 1].column) {
      out.values.back() += entry.value;
      continue;
    }
    if (new_row) {
      if (i > 0) out.row_start.push_back(static_cast<int64_t>(out.columns.size()));
      out.targets.push_back(entry.row % num_nodes);
      ++out.cell_start[static_cast<size_t>(entry.row / num_nodes + 1)];
    }
    out.columns.push_back(entry.column);
    out.values.push_back(entry.value);
  }
  if (!entries.empty()) out.row_start.push_back(static_cast<int64_t>(out.columns.size()));
  for (int64_t k = 0; k < kk; ++k) out.cell_start[static_cast<size_t>(k + 1)] += out.cell_start[static_cast<size_t>(k)];
  return out;
}

}  // namespace

SplineGraph spline_graph(const torch::Tensor& edge_index, const torch::Tensor& pseudo, int64_t num_nodes,
                         int64_t kernel_size) {
  if (edge_index.dim() != 2 || edge_index.size(0) != 2 || edge_index.scalar_type() != torch::kLong) {
    throw std::invalid_argument("spline_graph: edge_index must be an int64 [2,E] tensor");
  }
  if (pseudo.dim() != 2 || pseudo.size(0) != edge_index.size(1)) {
    throw std::invalid_argument("spline_graph: pseudo must be [E,2] with E the number of edges");
  }
  if (num_nodes < 1) throw std::invalid_argument("spline_graph: num_nodes must be positive");
  if (kernel_size < 2) throw std::invalid_argument("spline_graph: kernel_size must be at least 2");
  if (!torch::GradMode::is_enabled() && pseudo.scalar_type() == torch::kFloat && pseudo.size(1) == 2) {
    SplineGraph graph;
    graph.num_nodes = num_nodes;
    graph.kernel_size = kernel_size;
    graph.cell_rows = std::make_shared<const SplineCellRows>(cell_rows_from_edges(edge_index, pseudo, num_nodes, kernel_size));
    return graph;
  }
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
