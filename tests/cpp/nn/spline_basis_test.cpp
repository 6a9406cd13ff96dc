#include "support/catch_torch.h"


#include "core/nn/spline_basis.h"

using namespace autoblock;

namespace {

void check_row(const torch::Tensor& basis, const torch::Tensor& index, int64_t e, std::vector<double> b,
               std::vector<int64_t> w) {
  for (int64_t s = 0; s < 4; ++s) {
    INFO("edge " << e << ", product " << s);
    CHECK(basis[e][s].item<double>() == Approx(b[static_cast<size_t>(s)]).margin(1e-6));
    CHECK(index[e][s].item<int64_t>() == w[static_cast<size_t>(s)]);
  }
}

}  // namespace

// Products s = 0..3 use k_mod = (bit 0 of s, bit 1 of s) = (0,0), (1,0), (0,1), (1,1);
// index = ((floor v0 + k0) % K) + ((floor v1 + k1) % K) * K; basis = f(v0, k0) * f(v1, k1) with
// f(v, 0) = 1 - frac v, f(v, 1) = frac v.
TEST_CASE("spline_basis matches hand-computed tables for K = 5", "[nn][spline]") {
  const torch::Tensor pseudo = torch::tensor({0.1f, 0.3f,     // v = (0.4, 1.2): floor (0,1), frac (0.4, 0.2)
                                              0.0f, 0.0f,     // v = (0, 0): exactly on the first knot
                                              1.0f, 1.0f,     // v = (4, 4): exactly on the last knot
                                              1.0f, 0.0f,     // v = (4, 0)
                                              0.9f, 0.55f,    // v = (3.6, 2.2): floor (3,2), frac (0.6, 0.2)
                                              0.5f, 0.75f})   // v = (2, 3): on inner knots
                                   .view({6, 2});
  const auto [basis, index] = spline_basis(pseudo, 5);
  REQUIRE(basis.sizes() == torch::IntArrayRef({6, 4}));
  REQUIRE(index.sizes() == torch::IntArrayRef({6, 4}));
  CHECK(index.scalar_type() == torch::kLong);
  CHECK(basis.scalar_type() == torch::kFloat);
  // (0.4, 1.2): indices 0+1*5=5, 1+5=6, 0+2*5=10, 1+10=11; basis 0.6*0.8, 0.4*0.8, 0.6*0.2, 0.4*0.2.
  check_row(basis, index, 0, {0.48, 0.32, 0.12, 0.08}, {5, 6, 10, 11});
  // (0, 0): indices 0, 1, 0+1*5=5, 1+5=6; basis 1*1, 0*1, 1*0, 0*0.
  check_row(basis, index, 1, {1, 0, 0, 0}, {0, 1, 5, 6});
  // (4, 4): the upper knot wraps, (4+1) % 5 = 0: indices 4+4*5=24, 0+20=20, 4+0=4, 0; basis 1, 0, 0, 0.
  check_row(basis, index, 2, {1, 0, 0, 0}, {24, 20, 4, 0});
  // (4, 0): indices 4+0=4, 0+0=0, 4+1*5=9, 0+5=5.
  check_row(basis, index, 3, {1, 0, 0, 0}, {4, 0, 9, 5});
  // (3.6, 2.2): indices 3+2*5=13, 4+10=14, 3+3*5=18, 4+15=19; basis 0.4*0.8, 0.6*0.8, 0.4*0.2, 0.6*0.2.
  check_row(basis, index, 4, {0.32, 0.48, 0.08, 0.12}, {13, 14, 18, 19});
  // (2, 3): indices 2+3*5=17, 3+15=18, 2+4*5=22, 3+20=23; basis 1, 0, 0, 0.
  check_row(basis, index, 5, {1, 0, 0, 0}, {17, 18, 22, 23});
}

TEST_CASE("spline_basis matches a hand-computed table for K = 3", "[nn][spline]") {
  // (0.25, 0.75) * (K - 1) = (0.5, 1.5): floor (0,1), frac (0.5, 0.5); indices 0+1*3=3, 1+3=4,
  // 0+2*3=6, 1+6=7; every basis 0.5*0.5 = 0.25.
  // (1, 0.5) * 2 = (2, 1): indices 2+1*3=5, ((2+1)%3=0)+3=3, 2+2*3=8, 0+6=6; basis 1, 0, 0, 0.
  const torch::Tensor pseudo = torch::tensor({0.25, 0.75, 1.0, 0.5}, torch::kDouble).view({2, 2});
  const auto [basis, index] = spline_basis(pseudo, 3);
  CHECK(basis.scalar_type() == torch::kDouble);
  check_row(basis, index, 0, {0.25, 0.25, 0.25, 0.25}, {3, 4, 6, 7});
  check_row(basis, index, 1, {1, 0, 0, 0}, {5, 3, 8, 6});
}

TEST_CASE("spline_basis is a partition of unity with indices in range", "[nn][spline]") {
  torch::manual_seed(1);
  const torch::Tensor pseudo = torch::rand({500, 2});
  const auto [basis, index] = spline_basis(pseudo, 5);
  CHECK(torch::allclose(basis.sum(1), torch::ones({500}), 1e-5, 1e-6));
  CHECK(basis.min().item<float>() >= 0.f);
  CHECK(index.min().item<int64_t>() >= 0);
  CHECK(index.max().item<int64_t>() < 25);
  // The weighted mean of the knots' coordinates reproduces v = pseudo * (K - 1) (degree 1 is linear
  // interpolation) away from the last knot, where the upper index wraps to 0 with basis 0.
  const torch::Tensor knot_x = index.remainder(5).to(torch::kFloat), knot_y = index.div(5, "floor").to(torch::kFloat);
  CHECK(torch::allclose((basis * knot_x).sum(1), pseudo.select(1, 0) * 4, 1e-4, 1e-5));
  CHECK(torch::allclose((basis * knot_y).sum(1), pseudo.select(1, 1) * 4, 1e-4, 1e-5));
}

TEST_CASE("spline_basis rejects bad input", "[nn][spline]") {
  CHECK_THROWS_AS(spline_basis(torch::rand({3, 3}), 5), std::invalid_argument);
  CHECK_THROWS_AS(spline_basis(torch::rand({3, 2}), 1), std::invalid_argument);
  CHECK_THROWS_AS(spline_basis(torch::ones({3, 2}, torch::kLong), 5), std::invalid_argument);
}
