// Threads for the networks' arithmetic. Two pools are at work: LibTorch's intra-op threads
// (OpenMP; 1 by default on this machine) and, for matrix products, OpenBLAS's own pthreads (as many
// as cores by default). Both at 2 on a 2-core machine oversubscribe it: OpenMP threads spin while
// OpenBLAS needs the cores, and forward passes get slower and erratic (see bench_value_network).
#pragma once

namespace autoblock {

// Inputs: threads >= 1. Effect: OpenBLAS's thread count, when the process's BLAS is OpenBLAS.
// Output: true when it was set; false when no OpenBLAS is loaded (then nothing changes).
bool set_blas_threads(int threads);

// Output: OpenBLAS's thread count, or -1 when no OpenBLAS is loaded.
int blas_threads();

}  // namespace autoblock
