#include "support/catch_torch.h"


#include <sstream>

#include "core/common/error.h"
#include "core/graph/part_graph.h"
#include "core/nn/graph_batch.h"
#include "core/nn/residual_block.h"
#include "core/nn/tensor_convert.h"
#include "core/nn/value_network.h"
#include "support/test_shapes.h"

using namespace autoblock;

namespace {

// Parameters of a SplineConv, a batch norm (weight and bias; running statistics are buffers).
int64_t conv_parameters(int64_t in, int64_t out, int64_t k) { return k * k * in * out + in * out + out; }
int64_t bn_parameters(int64_t width) { return 2 * width; }

int64_t parameter_count(torch::nn::Module& module) {
  int64_t total = 0;
  for (const auto& p : module.parameters()) total += p.numel();
  return total;
}

std::vector<PartGraph> some_graphs(int count, std::uint64_t seed) {
  std::vector<PartGraph> graphs;
  for (const GeneratedShape& s : test::generated_shapes(count, seed, GeneratorOptions{})) {
    graphs.push_back(part_graph(make_grid_face(s.polygon).whole));
  }
  return graphs;
}

GraphBatch batch_of(const std::vector<PartGraph>& graphs) {
  std::vector<const PartGraph*> pointers;
  for (const PartGraph& g : graphs) pointers.push_back(&g);
  return batch_graphs(pointers);
}

// The preset's network in eval mode, its batch norms given non-trivial running statistics first
// (three training-mode passes over batch).
ValueNetwork in_eval_mode(const std::string& name, const GraphBatch& batch) {
  ValueNetwork net(ValueNetworkConfig::by_name(name));
  net->train();
  for (int k = 0; k < 3; ++k) net(batch.x, batch.edge_index, batch.pseudo);
  net->eval();
  return net;
}

}  // namespace

TEST_CASE("ValueNetwork presets have the paper's layers", "[nn][value]") {
  const ValueNetworkConfig paper = ValueNetworkConfig::paper();
  CHECK(paper.name == "paper");
  CHECK(paper.first_width == 64);
  CHECK((paper.block_widths == std::vector<int64_t>{128, 256, 128, 64, 32, 16, 8}));
  CHECK(paper.kernel_size == 5);
  CHECK(ValueNetworkConfig::by_name("small").name == "small");
  CHECK(ValueNetworkConfig::by_name("paper").block_widths == paper.block_widths);
  CHECK_THROWS_AS(ValueNetworkConfig::by_name("huge"), InputError);
  CHECK_THROWS_AS(ValueNetwork(ValueNetworkConfig{"bad", 0, {4}, 5}), InputError);

  for (const std::string& name : ValueNetworkConfig::names()) {
    const ValueNetworkConfig config = ValueNetworkConfig::by_name(name);
    ValueNetwork net(config);
    const int64_t k = config.kernel_size;
    // Input conv + BN, per block two convs + two BNs (+ a skip conv and BN when the width
    // changes), output conv without BN.
    int64_t expected = conv_parameters(3, config.first_width, k) + bn_parameters(config.first_width);
    int64_t width = config.first_width;
    for (int64_t next : config.block_widths) {
      expected += conv_parameters(width, next, k) + conv_parameters(next, next, k) + 2 * bn_parameters(next);
      if (next != width) expected += conv_parameters(width, next, k) + bn_parameters(next);
      width = next;
    }
    expected += conv_parameters(width, 1, k);
    INFO(name);
    CHECK(parameter_count(*net) == expected);
    CHECK(net->blocks->size() == config.block_widths.size());
  }
}

TEST_CASE("a residual block without a width change has an identity skip path", "[nn][value]") {
  ResidualBlock same(8, 8, 5), wider(8, 16, 5);
  CHECK_FALSE(same->skip_conv);
  CHECK_FALSE(same->skip_bn);
  CHECK(wider->skip_conv);
  CHECK(wider->skip_bn);
  // With the main path's last batch norm scaled to 0 the block is ELU(x) exactly.
  torch::NoGradGuard no_grad;
  same->bn2->weight.zero_();
  same->eval();
  const torch::Tensor x = torch::randn({5, 8});
  const torch::Tensor edge_index = torch::tensor({0, 1, 1, 2, 3, 4, 4, 3}, torch::kLong).view({2, 4});
  const SplineGraph graph = spline_graph(edge_index, torch::rand({4, 2}), 5, 5);
  CHECK(torch::allclose(same(x, graph), torch::elu(x)));
}

TEST_CASE("ValueNetwork gives one value per node for both presets", "[nn][value]") {
  const std::vector<PartGraph> graphs = some_graphs(1, 21);
  const GraphBatch batch = graph_batch_of(graphs[0]);
  for (const std::string& name : ValueNetworkConfig::names()) {
    ValueNetwork net(ValueNetworkConfig::by_name(name));
    net->eval();
    torch::NoGradGuard no_grad;
    const torch::Tensor values = net(batch.x, batch.edge_index, batch.pseudo);
    INFO(name);
    REQUIRE(values.sizes() == torch::IntArrayRef({graphs[0].node_count()}));
    CHECK(torch::isfinite(values).all().item<bool>());
    CHECK(vertex_values(values, batch).size(0) == static_cast<int64_t>(graphs[0].vertex_nodes.size()));
  }
}

TEST_CASE("ValueNetwork in eval mode: a batch equals its graphs one by one", "[nn][value]") {
  torch::manual_seed(8);
  const std::vector<PartGraph> graphs = some_graphs(4, 22);
  const GraphBatch batch = batch_of(graphs);
  for (const std::string& name : ValueNetworkConfig::names()) {
    ValueNetwork net = in_eval_mode(name, batch);
    torch::NoGradGuard no_grad;
    const torch::Tensor together = net(batch.x, batch.edge_index, batch.pseudo);
    INFO(name);
    for (size_t g = 0; g < graphs.size(); ++g) {
      const GraphBatch one = graph_batch_of(graphs[g]);
      const torch::Tensor alone = net(one.x, one.edge_index, one.pseudo);
      const torch::Tensor part = together.slice(0, batch.node_offsets[g], batch.node_offsets[g + 1]);
      CHECK(torch::allclose(part, alone, 1e-4, 1e-5));
    }
    // In training mode batch statistics couple the graphs: the same check would not hold.
  }
}

TEST_CASE("ValueNetwork: the forward pass without gradients (by kernel cells) equals the one with them", "[nn][value]") {
  // Deployment runs under NoGradGuard, where SplineConv multiplies only the nonzero (node, cell)
  // blocks (spline_weighting.h); training runs with gradients, through the dense product.
  torch::manual_seed(9);
  const std::vector<PartGraph> graphs = some_graphs(6, 23);
  const GraphBatch batch = batch_of(graphs);
  for (const std::string& name : ValueNetworkConfig::names()) {
    ValueNetwork net = in_eval_mode(name, batch);
    const torch::Tensor with_gradients = net(batch.x, batch.edge_index, batch.pseudo).detach();
    torch::NoGradGuard no_grad;
    const torch::Tensor without = net(batch.x, batch.edge_index, batch.pseudo);
    INFO(name);
    CHECK(torch::allclose(without, with_gradients, 1e-4, 1e-5));
  }
}

TEST_CASE("ValueNetwork: gradients reach every parameter", "[nn][value]") {
  torch::manual_seed(9);
  const std::vector<PartGraph> graphs = some_graphs(2, 23);
  const GraphBatch batch = batch_graphs({&graphs[0], &graphs[1]});
  for (const std::string& name : ValueNetworkConfig::names()) {
    ValueNetwork net(ValueNetworkConfig::by_name(name));
    net->train();
    const torch::Tensor values = net(batch.x, batch.edge_index, batch.pseudo);
    // A loss on the model-vertex values only, as the agent uses them.
    const torch::Tensor v = vertex_values(values, batch);
    (v * torch::randn(v.sizes())).sum().backward();
    INFO(name);
    for (const auto& item : net->named_parameters()) {
      INFO(item.key());
      REQUIRE(item.value().grad().defined());
      CHECK(item.value().grad().abs().sum().item<double>() > 0);
    }
  }
}

TEST_CASE("ValueNetwork round-trips through torch::save and torch::load", "[nn][value]") {
  torch::manual_seed(10);
  const std::vector<PartGraph> graphs = some_graphs(1, 24);
  const GraphBatch batch = graph_batch_of(graphs[0]);
  ValueNetwork trained(ValueNetworkConfig::small());
  trained->train();
  trained(batch.x, batch.edge_index, batch.pseudo);  // moves the batch norms' running statistics
  std::stringstream stream;
  torch::save(trained, stream);
  torch::manual_seed(11);
  ValueNetwork loaded(ValueNetworkConfig::small());
  torch::load(loaded, stream);
  trained->eval();
  loaded->eval();
  torch::NoGradGuard no_grad;
  CHECK(torch::equal(trained(batch.x, batch.edge_index, batch.pseudo), loaded(batch.x, batch.edge_index, batch.pseudo)));
}
