#include "support/catch_torch.h"


#include "core/nn/mlp.h"

using namespace autoblock;

TEST_CASE("Mlp has the requested layers and shapes", "[nn][mlp]") {
  // ModuleHolder forwards its arguments through a template: brace lists need their type spelled.
  Mlp actor(9, std::vector<int64_t>{256, 128, 64}, 2, false);
  REQUIRE(actor->layers.size() == 4);
  int64_t parameters = 0;
  for (const auto& p : actor->parameters()) parameters += p.numel();
  CHECK(parameters == (9 * 256 + 256) + (256 * 128 + 128) + (128 * 64 + 64) + (64 * 2 + 2));
  CHECK(actor(torch::randn({5, 9})).sizes() == torch::IntArrayRef({5, 2}));
  CHECK(actor(torch::randn({9})).sizes() == torch::IntArrayRef({2}));
  Mlp single(3, std::vector<int64_t>{}, 4, false);
  CHECK(single->layers.size() == 1);
  CHECK(single(torch::randn({2, 3})).sizes() == torch::IntArrayRef({2, 4}));
  CHECK_THROWS_AS(Mlp(9, std::vector<int64_t>{0}, 2, false), std::invalid_argument);
}

TEST_CASE("Mlp applies ReLU after hidden layers, and after the output only when asked", "[nn][mlp]") {
  torch::manual_seed(4);
  Mlp linear_out(4, std::vector<int64_t>{8}, 3, false), relu_out(4, std::vector<int64_t>{8}, 3, true);
  const torch::Tensor x = 3 * torch::randn({200, 4});
  torch::NoGradGuard no_grad;
  CHECK(linear_out(x).min().item<float>() < 0);
  CHECK(relu_out(x).min().item<float>() >= 0);
  CHECK(relu_out(x).max().item<float>() > 0);
  // By hand: relu(relu(x W0^T + b0) W1^T + b1).
  const auto& l0 = relu_out->layers[0];
  const auto& l1 = relu_out->layers[1];
  const torch::Tensor expected = torch::relu(torch::relu(x.mm(l0->weight.t()) + l0->bias).mm(l1->weight.t()) + l1->bias);
  CHECK(torch::allclose(relu_out(x), expected, 1e-5, 1e-6));
  const auto& m0 = linear_out->layers[0];
  const auto& m1 = linear_out->layers[1];
  CHECK(torch::allclose(linear_out(x), torch::relu(x.mm(m0->weight.t()) + m0->bias).mm(m1->weight.t()) + m1->bias,
                        1e-5, 1e-6));
}
