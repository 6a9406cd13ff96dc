#include "core/api/learned_runtime.h"

#include <atomic>
#include <mutex>

#include "core/common/plugin.h"

namespace autoblock {
namespace {

std::atomic<LearnedRuntime*> runtime{nullptr};

}  // namespace

LearnedRuntime& learned_runtime() {
  static std::mutex mutex;
  if (LearnedRuntime* r = runtime.load()) return *r;
  std::lock_guard<std::mutex> lock(mutex);
  if (!runtime.load()) {
    using Entry = LearnedRuntime* (*)();
    auto entry = reinterpret_cast<Entry>(
        plugin_symbol("libautoblock_learn.so", "autoblock_learned_runtime", "AUTOBLOCK_LEARN_LIBRARY"));
    runtime = entry();
  }
  return *runtime.load();
}

bool learned_runtime_loaded() { return runtime.load() != nullptr; }

}  // namespace autoblock
