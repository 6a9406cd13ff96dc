#include "core/sac/compute_threads.h"

#include <algorithm>

#include <ATen/Parallel.h>

namespace autoblock {

void set_compute_threads(int threads) { at::set_num_threads(std::max(1, threads)); }

}  // namespace autoblock
