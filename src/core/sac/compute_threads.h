// How many threads the networks' arithmetic may use (LibTorch's intra-op threads), without
// including LibTorch.
#pragma once

namespace autoblock {

// Inputs: threads, at least 1: LibTorch's intra-op threads (OpenBLAS is held at one thread, so
// that the two pools do not compete).
void set_compute_threads(int threads);

}  // namespace autoblock
