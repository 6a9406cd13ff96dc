// OCC_CATCH_SIGNALS jumps to the nearest handler only when OCC_CONVERT_SIGNALS is defined (Debian's
// OpenCASCADE is built with it); define it before any OpenCASCADE header.
#ifndef OCC_CONVERT_SIGNALS
#define OCC_CONVERT_SIGNALS
#endif

#include "core/io/isolated_call.h"

#include <OSD.hxx>
#include <Standard_ErrorHandler.hxx>
#include <Standard_Failure.hxx>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>

#include "core/common/error.h"

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define AUTOBLOCK_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define AUTOBLOCK_SANITIZED 1
#endif
#endif

namespace autoblock {
namespace {

constexpr char kOk = 'O';
constexpr char kError = 'E';
constexpr size_t kHeader = 1 + 16;  // kind, then the payload's length as 16 hexadecimal digits

// Runs work, turning every failure into a message. Returns true with work's text in out, or false
// with the message in out.
bool guarded(const std::function<std::string()>& work, std::string& out) {
  try {
    OCC_CATCH_SIGNALS
    out = work();
    return true;
  } catch (const Standard_Failure& e) {
    out = std::string("OpenCASCADE failed: ") + e.DynamicType()->Name() + ": " + e.GetMessageString();
  } catch (const std::bad_alloc&) {
    out = "it needs more memory than allowed (a count or size in it is probably wrong)";
  } catch (const std::exception& e) {
    out = e.what();
  }
  return false;
}

bool write_all(int fd, const char* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

// The child's address space now, in bytes (0 when unknown).
size_t address_space_now() {
  std::ifstream statm("/proc/self/statm");
  size_t pages = 0;
  if (!(statm >> pages)) return 0;
  return pages * static_cast<size_t>(::sysconf(_SC_PAGESIZE));
}

[[noreturn]] void child_main(int out, pid_t parent, const std::function<std::string()>& work, double budget_seconds) {
  // Die with the parent, and by our own alarm shortly after the parent's deadline.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(3);
  ::alarm(static_cast<unsigned>(std::ceil(budget_seconds)) + 2);
  // OpenCASCADE's readers print to std::cout: that is the parent's output, not ours.
  const int null = ::open("/dev/null", O_RDWR);
  if (null >= 0) {
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(null, 2);
    if (null > 2) ::close(null);
  }
#ifndef AUTOBLOCK_SANITIZED
  const size_t now = address_space_now();
  if (now > 0) {
    const rlim_t limit = static_cast<rlim_t>(now) + (rlim_t(4) << 30);
    struct rlimit rl {};
    if (::getrlimit(RLIMIT_AS, &rl) == 0 && (rl.rlim_max == RLIM_INFINITY || rl.rlim_max > limit)) {
      rl.rlim_cur = limit;
      ::setrlimit(RLIMIT_AS, &rl);
    }
  }
#endif
  // An access violation or a floating-point trap becomes an exception (OSD_SIGSEGV, ...) at the
  // OCC_CATCH_SIGNALS in guarded(); floating-point traps stay off (NaN and infinities are data).
  OSD::SetSignal(OSD_SignalMode_Set, false);
  std::string payload;
  const bool ok = guarded(work, payload);
  char header[kHeader + 1];
  std::snprintf(header, sizeof header, "%c%016zx", ok ? kOk : kError, payload.size());
  const bool sent = write_all(out, header, kHeader) && write_all(out, payload.data(), payload.size());
  ::_exit(sent ? 0 : 4);
}

std::string signal_text(int signal_number) {
  const char* name = ::strsignal(signal_number);
  return "signal " + std::to_string(signal_number) + (name ? std::string(", ") + name : std::string());
}

}  // namespace

double read_budget_seconds() {
  const char* text = std::getenv("AUTOBLOCK_READ_TIMEOUT");
  if (text && *text) {
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end && *end == '\0' && std::isfinite(value) && value >= 0) return value;
  }
  return 30.0;
}

std::string run_isolated(const std::function<std::string()>& work, const std::string& what, double budget_seconds) {
  std::string out;
  int fds[2];
  if (budget_seconds <= 0 || ::pipe2(fds, O_CLOEXEC) != 0) {
    if (!guarded(work, out)) throw InputError(out);
    return out;
  }
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    if (!guarded(work, out)) throw InputError(out);
    return out;
  }
  if (pid == 0) {
    ::close(fds[0]);
    child_main(fds[1], parent, work, budget_seconds);
  }
  ::close(fds[1]);

  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline =
      Clock::now() + std::chrono::milliseconds(static_cast<long long>(budget_seconds * 1000.0));
  std::string received;
  bool timed_out = false;
  char buffer[65536];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      timed_out = true;
      break;
    }
    struct pollfd p {fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) break;  // end: the child has exited (or closed its end)
    received.append(buffer, static_cast<size_t>(n));
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  pid_t waited;
  do {
    waited = ::waitpid(pid, &status, 0);
  } while (waited < 0 && errno == EINTR);
  // waited < 0 (ECHILD) when the embedding application reaps children itself (SIGCHLD ignored):
  // then the message alone decides.
  if (timed_out) {
    char budget[32];
    std::snprintf(budget, sizeof budget, "%g", budget_seconds);
    throw InputError(what + ": reading took longer than " + budget +
                     " s and was stopped; the input is probably malformed (AUTOBLOCK_READ_TIMEOUT sets the limit)");
  }
  if (received.size() >= kHeader && (received[0] == kOk || received[0] == kError)) {
    const size_t size = std::strtoull(received.substr(1, kHeader - 1).c_str(), nullptr, 16);
    if (received.size() == kHeader + size) {
      out = received.substr(kHeader);
      if (received[0] == kError) throw InputError(out);
      return out;
    }
  }
  if (waited == pid && WIFSIGNALED(status)) {
    throw InputError(what + ": the reader crashed on it (" + signal_text(WTERMSIG(status)) +
                     "); the input is probably malformed");
  }
  throw InputError(what + ": the reader failed on it without a message; the input is probably malformed");
}

}  // namespace autoblock
