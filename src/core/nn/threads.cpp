#include "core/nn/threads.h"

#include <dlfcn.h>

namespace autoblock {
namespace {

// OpenBLAS's C entry points, looked up at run time: LibTorch reaches the BLAS through Debian's
// libblas.so.3 alternative, which may or may not be OpenBLAS.
using SetThreads = void (*)(int);
using GetThreads = int (*)();

}  // namespace

bool set_blas_threads(int threads) {
  if (threads < 1) return false;
  const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (!set) return false;
  set(threads);
  return true;
}

int blas_threads() {
  const auto get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  return get ? get() : -1;
}

}  // namespace autoblock
