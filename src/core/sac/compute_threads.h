// How many threads the networks' arithmetic may use (LibTorch's intra-op threads), without
// including LibTorch.
#pragma once

namespace autoblock {

// Inputs: threads, at least 1.
void set_compute_threads(int threads);

}  // namespace autoblock
