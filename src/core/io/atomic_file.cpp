#include "core/io/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <random>

#include "core/common/error.h"

namespace autoblock {
namespace {

namespace fs = std::filesystem;

const char* const kMarker = ".autoblock-tmp-";

// fsync a file or folder by path; false when it cannot be opened or synced.
bool sync_path(const std::string& path, bool folder) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (folder ? O_DIRECTORY : 0));
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0 || errno == EINVAL;  // EINVAL: a file system without fsync
  ::close(fd);
  return ok;
}

bool process_gone(long pid) { return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

}  // namespace

std::vector<std::string> stale_temporary_files(const std::string& path) {
  std::vector<std::string> stale;
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string prefix = target.filename().string() + kMarker;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = name.substr(prefix.size());
    const size_t dash = rest.find('-');
    if (dash == 0 || dash == std::string::npos) continue;
    long pid = 0;
    try {
      pid = std::stol(rest.substr(0, dash));
    } catch (const std::exception&) {
      continue;
    }
    if (process_gone(pid)) stale.push_back(it->path().string());
  }
  return stale;
}

void write_file_atomically(const std::string& path, const std::function<bool(const std::string& temporary)>& write) {
  std::error_code ec;
  const fs::path target(path);
  if (target.has_parent_path() && !fs::is_directory(target.parent_path(), ec)) {
    throw InputError(path + ": the folder " + target.parent_path().string() + " does not exist");
  }
  if (fs::is_directory(target, ec)) throw InputError(path + ": is a directory, not a file");
  for (const std::string& leftover : stale_temporary_files(path)) fs::remove(leftover, ec);

  std::random_device random;
  const std::string temporary =
      path + kMarker + std::to_string(::getpid()) + "-" + std::to_string(random()) + target.extension().string();
  bool written = false;
  try {
    written = write(temporary);
  } catch (...) {
    fs::remove(temporary, ec);
    throw;
  }
  // The content reaches the disk before the rename makes it visible; the rename reaches the disk
  // with the folder's sync.
  if (!written || !fs::is_regular_file(temporary, ec) || !sync_path(temporary, false) ||
      (fs::rename(temporary, path, ec), ec)) {
    fs::remove(temporary, ec);
    throw InputError(path + ": cannot write the file");
  }
  sync_path(target.has_parent_path() ? target.parent_path().string() : std::string("."), true);
}

}  // namespace autoblock
