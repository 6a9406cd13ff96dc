#include "core/sac/compute_threads.h"

#include <algorithm>

#include <ATen/Parallel.h>

#include "core/nn/threads.h"

namespace autoblock {

void set_compute_threads(int threads) {
  at::set_num_threads(std::max(1, threads));
  set_blas_threads(1);  // OpenBLAS's own pool would compete with LibTorch's (nn/threads.h)
}

}  // namespace autoblock
