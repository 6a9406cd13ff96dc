#include "support/catch_torch.h"


#include <tuple>
#include <vector>

#include "core/nn/spline_basis.h"
#include "core/nn/spline_conv.h"
#include "core/nn/spline_weighting.h"

using namespace autoblock;

namespace {

struct RandomGraph {
  torch::Tensor x, edge_index, pseudo;
};

// Inputs: nodes, edges, channels, dtype. Output: random edges among the first nodes - 2 nodes
// (the last two never receive a message), random pseudo in [0,1] with a few exact 0s and 1s.
RandomGraph random_graph(int64_t nodes, int64_t edges, int64_t channels, torch::Dtype dtype) {
  RandomGraph g;
  g.x = torch::randn({nodes, channels}, dtype);
  const torch::Tensor source = torch::randint(nodes, {edges}, torch::kLong);
  const torch::Tensor target = torch::randint(nodes - 2, {edges}, torch::kLong);
  g.edge_index = torch::stack({source, target});
  g.pseudo = torch::rand({edges, 2}, dtype);
  if (edges >= 3) {
    g.pseudo[0][0] = 0.0;
    g.pseudo[1][1] = 1.0;
    g.pseudo[2][0] = 1.0;
    g.pseudo[2][1] = 1.0;
  }
  return g;
}

// The definition, one edge at a time: mean over incoming edges of
// sum_s basis[e,s] x[source] W[index[e,s]], plus x root + bias.
torch::Tensor naive_spline_conv(const torch::Tensor& x, const torch::Tensor& edge_index, const torch::Tensor& pseudo,
                                const torch::Tensor& weight, const torch::Tensor& root, const torch::Tensor& bias,
                                int64_t kernel_size) {
  const auto [basis, index] = spline_basis(pseudo, kernel_size);
  const int64_t nodes = x.size(0);
  torch::Tensor sum = torch::zeros({nodes, weight.size(2)}, x.options());
  std::vector<int> count(static_cast<size_t>(nodes), 0);
  for (int64_t e = 0; e < edge_index.size(1); ++e) {
    const int64_t s = edge_index[0][e].item<int64_t>(), t = edge_index[1][e].item<int64_t>();
    torch::Tensor message = torch::zeros({weight.size(2)}, x.options());
    for (int64_t p = 0; p < 4; ++p) {
      message += basis[e][p] * torch::matmul(x[s], weight[index[e][p].item<int64_t>()]);
    }
    sum[t] += message;
    ++count[static_cast<size_t>(t)];
  }
  for (int64_t t = 0; t < nodes; ++t) {
    if (count[static_cast<size_t>(t)] > 0) sum[t] /= count[static_cast<size_t>(t)];
  }
  return sum + torch::matmul(x, root) + bias;
}

}  // namespace

TEST_CASE("SplineConv equals a per-edge loop on random graphs", "[nn][spline]") {
  torch::manual_seed(3);
  for (int64_t kernel : {5, 3}) {
    for (auto [nodes, edges, in, out] : std::vector<std::array<int64_t, 4>>{{6, 10, 3, 4}, {30, 150, 8, 5}, {12, 1, 2, 3}}) {
      INFO("K " << kernel << ", " << nodes << " nodes, " << edges << " edges, " << in << " -> " << out);
      SplineConv conv(in, out, kernel);
      torch::NoGradGuard no_grad;
      conv->bias.uniform_(-1, 1);  // the bias starts at 0: make it count
      const RandomGraph g = random_graph(nodes, edges, in, torch::kFloat);
      const torch::Tensor got = conv(g.x, g.edge_index, g.pseudo);
      const torch::Tensor expected =
          naive_spline_conv(g.x, g.edge_index, g.pseudo, conv->weight, conv->root, conv->bias, kernel);
      REQUIRE(got.sizes() == torch::IntArrayRef({nodes, out}));
      CHECK(torch::allclose(got, expected, 1e-4, 1e-5));
      // The per-edge kernel gives the same messages as the loop.
      const auto [basis, index] = spline_basis(g.pseudo, kernel);
      const torch::Tensor messages = spline_weighting(g.x, g.edge_index[0], conv->weight, basis, index);
      REQUIRE(messages.sizes() == torch::IntArrayRef({edges, out}));
      for (int64_t e = 0; e < edges; e += std::max<int64_t>(1, edges / 7)) {
        torch::Tensor m = torch::zeros({out});
        for (int64_t p = 0; p < 4; ++p) {
          m += basis[e][p] * torch::matmul(g.x[g.edge_index[0][e].item<int64_t>()], conv->weight[index[e][p].item<int64_t>()]);
        }
        CHECK(torch::allclose(messages[e], m, 1e-4, 1e-5));
      }
    }
  }
}

TEST_CASE("SplineConv takes the mean of incoming messages and 0 at nodes without any", "[nn][spline]") {
  // Nodes 0, 1, 2; edges 0 -> 1 with pseudo (0,0) (kernel 0 only) and 2 -> 1 with pseudo (1,1)
  // (kernel K*K-1 only); nothing reaches 0 or 2.
  SplineConv conv(2, 3, 5);
  torch::NoGradGuard no_grad;
  conv->bias.uniform_(-1, 1);
  const torch::Tensor x = torch::tensor({1.f, 2.f, -1.f, 0.5f, 3.f, -2.f}).view({3, 2});
  const torch::Tensor edge_index = torch::tensor({0, 2, 1, 1}, torch::kLong).view({2, 2});
  const torch::Tensor pseudo = torch::tensor({0.f, 0.f, 1.f, 1.f}).view({2, 2});
  const torch::Tensor out = conv(x, edge_index, pseudo);
  const torch::Tensor self = torch::matmul(x, conv->root) + conv->bias;
  CHECK(torch::allclose(out[0], self[0]));
  CHECK(torch::allclose(out[2], self[2]));
  const torch::Tensor mean = 0.5 * (torch::matmul(x[0], conv->weight[0]) + torch::matmul(x[2], conv->weight[24]));
  CHECK(torch::allclose(out[1], self[1] + mean, 1e-5, 1e-6));
  // No edges at all: every node gets only its root term.
  const torch::Tensor none = conv(x, torch::empty({2, 0}, torch::kLong), torch::empty({0, 2}));
  CHECK(torch::allclose(none, self));
}

TEST_CASE("SplineConv gradients match finite differences in double precision", "[nn][spline]") {
  torch::manual_seed(5);
  const int64_t in = 3, out = 2, kernel = 3;
  SplineConv conv(in, out, kernel);
  conv->to(torch::kDouble);
  {
    torch::NoGradGuard no_grad;
    conv->bias.uniform_(-1, 1);
  }
  RandomGraph g = random_graph(7, 16, in, torch::kDouble);
  g.x.requires_grad_(true);
  const torch::Tensor probe = torch::randn({7, out}, torch::kDouble);  // loss = sum(out * probe)
  auto loss = [&]() { return (conv(g.x, g.edge_index, g.pseudo) * probe).sum(); };
  for (auto* p : {&g.x, &conv->weight, &conv->root, &conv->bias}) {
    if (p->grad().defined()) p->grad().zero_();
  }
  loss().backward();
  const double h = 1e-6;
  const std::vector<std::pair<const char*, torch::Tensor*>> tensors{
      {"x", &g.x}, {"weight", &conv->weight}, {"root", &conv->root}, {"bias", &conv->bias}};
  for (const auto& [name, tensor] : tensors) {
    const torch::Tensor analytic = tensor->grad().clone();
    REQUIRE(analytic.defined());
    torch::NoGradGuard no_grad;
    torch::Tensor flat = tensor->view({-1});
    double worst = 0, largest = 0;
    for (int64_t k = 0; k < flat.numel(); ++k) {
      const double saved = flat[k].item<double>();
      flat[k] = saved + h;
      const double up = loss().item<double>();
      flat[k] = saved - h;
      const double down = loss().item<double>();
      flat[k] = saved;
      const double numeric = (up - down) / (2 * h);
      worst = std::max(worst, std::abs(numeric - analytic.view({-1})[k].item<double>()));
      largest = std::max(largest, std::abs(numeric));
    }
    INFO(name << ": largest |gradient| " << largest << ", worst difference " << worst);
    CHECK(largest > 1e-3);  // the check is not vacuous
    CHECK(worst < 1e-7);
  }
}

TEST_CASE("SplineConv rejects inputs that do not fit", "[nn][spline]") {
  SplineConv conv(3, 4, 5);
  const torch::Tensor edge_index = torch::tensor({0, 1}, torch::kLong).view({2, 1});
  const torch::Tensor pseudo = torch::rand({1, 2});
  CHECK_THROWS_AS(conv(torch::rand({2, 2}), edge_index, pseudo), std::invalid_argument);
  CHECK_THROWS_AS(conv(torch::rand({2, 3}), torch::tensor({0, 2}, torch::kLong).view({2, 1}), pseudo),
                  std::invalid_argument);
  CHECK_THROWS_AS(conv(torch::rand({2, 3}), edge_index, torch::rand({2, 2})), std::invalid_argument);
  CHECK_THROWS_AS(conv->forward_on(torch::rand({2, 3}), spline_graph(edge_index, pseudo, 2, 3)), std::invalid_argument);
  CHECK_THROWS_AS(SplineConv(0, 4, 5), std::invalid_argument);
}

TEST_CASE("without gradients the mean weighting by kernel cells equals the dense product", "[nn][spline]") {
  // spline_graph built with gradients off keeps its rows by cell; spline_mean_weighting then sums
  // over the nonzero (node, cell) blocks only. It must give the dense form's values.
  torch::manual_seed(31);
  for (const auto& [nodes, edges, in, out, k] : std::vector<std::tuple<int64_t, int64_t, int64_t, int64_t, int64_t>>{
           {1, 0, 3, 4, 5}, {12, 30, 3, 32, 5}, {40, 200, 32, 64, 5}, {57, 120, 64, 16, 3}, {200, 1100, 16, 1, 5}}) {
    const RandomGraph g = random_graph(nodes + 2, edges, in, torch::kFloat);
    const torch::Tensor weight = torch::randn({k * k, in, out});
    const SplineGraph dense_graph = spline_graph(g.edge_index, g.pseudo, nodes + 2, k);
    REQUIRE_FALSE(dense_graph.cell_rows);  // gradients on: the dense operator only
    const torch::Tensor dense = spline_mean_weighting(g.x, weight, dense_graph);
    torch::NoGradGuard no_grad;
    const SplineGraph cell_graph = spline_graph(g.edge_index, g.pseudo, nodes + 2, k);
    REQUIRE(cell_graph.cell_rows);
    const SplineCellRows& cells = *cell_graph.cell_rows;
    CHECK_FALSE(cell_graph.mean_operator.defined());
    CHECK(cells.cell_start.size() == static_cast<size_t>(k * k + 1));
    CHECK(cells.cell_start.back() == static_cast<int64_t>(cells.targets.size()));
    CHECK(cells.row_start.size() == cells.targets.size() + 1);
    CHECK(cells.row_start.back() <= dense_graph.mean_operator._nnz());  // exact zeros left out
    const torch::Tensor by_cells = spline_mean_weighting(g.x, weight, cell_graph);
    INFO(nodes << " nodes, " << edges << " edges, " << in << " -> " << out << ", K " << k);
    REQUIRE(by_cells.sizes() == dense.sizes());
    CHECK(torch::allclose(by_cells, dense, 1e-5, 1e-5));
    // The last two nodes receive nothing: 0 there.
    CHECK(by_cells.slice(0, nodes, nodes + 2).abs().max().item<float>() == 0.0f);
    // Such a graph cannot take gradients: a clear error, not a wrong result.
    torch::AutoGradMode with_gradients(true);
    CHECK_THROWS_AS(spline_mean_weighting(g.x, weight, cell_graph), std::invalid_argument);
  }
}
