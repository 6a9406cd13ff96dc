#include "core/common/plugin.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace autoblock {
namespace {

// The folder this library (libautoblock_core.so) was loaded from.
std::string own_folder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&plugin_symbol_loaded), &info) == 0 || !info.dli_fname) return ".";
  return std::filesystem::path(info.dli_fname).parent_path().string();
}

}  // namespace

bool plugin_symbol_loaded(const char* symbol) { return dlsym(RTLD_DEFAULT, symbol) != nullptr; }

void* plugin_symbol(const std::string& library, const char* symbol, const char* env) {
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  if (void* found = dlsym(RTLD_DEFAULT, symbol)) return found;
  std::string path;
  if (const char* value = env ? std::getenv(env) : nullptr; value && *value) {
    path = value;
  } else {
    path = (std::filesystem::path(own_folder()) / library).string();
  }
  // RTLD_GLOBAL: a later lookup by name (above) finds it without loading it again.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (!handle) {
    const char* why = dlerror();
    throw std::runtime_error("cannot load " + path + ": " + (why ? why : "unknown error"));
  }
  void* found = dlsym(handle, symbol);
  if (!found) throw std::runtime_error(path + " has no entry point " + symbol);
  return found;
}

}  // namespace autoblock
