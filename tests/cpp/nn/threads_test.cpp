#include "support/catch_torch.h"


#include "core/nn/threads.h"

using namespace autoblock;

TEST_CASE("set_blas_threads sets OpenBLAS's thread count when OpenBLAS is the BLAS", "[nn][threads]") {
  torch::mm(torch::ones({2, 2}), torch::ones({2, 2}));  // the BLAS is loaded with LibTorch anyway
  const int before = blas_threads();
  if (before == -1) {
    WARN("the BLAS is not OpenBLAS: nothing to set");
    CHECK_FALSE(set_blas_threads(1));
    return;
  }
  CHECK(before >= 1);
  REQUIRE(set_blas_threads(1));
  CHECK(blas_threads() == 1);
  CHECK_FALSE(set_blas_threads(0));
  CHECK(blas_threads() == 1);
  REQUIRE(set_blas_threads(before));
  CHECK(blas_threads() == before);
}
