#include "gpu/isolated_gpu.hpp"

#include "base/stopwatch.hpp"
#include "gpu/draw_list_wire.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace twinraster {
namespace {

[[noreturn]] void ThrowErrno(const char* what) { throw std::system_error(errno, std::generic_category(), what); }

// The child's messages: kDevice once it has its device, then for each list one of the others.
// kRendered is followed by the pixels. The parent's requests are a length and an encoded list.
enum Tag : char { kDevice = 'D', kRendered = 'R', kUnavailable = 'U', kBadList = 'B', kFailed = 'X' };

// Whole messages written on a stream socket. MSG_NOSIGNAL: a peer that died is an error to report,
// not a SIGPIPE that would kill the writer.
class Writer {
 public:
  explicit Writer(char tag) { bytes_.push_back(tag); }
  Writer() = default;
  Writer& U32(std::uint32_t v) { return Raw(&v, sizeof v); }
  Writer& U64(std::uint64_t v) { return Raw(&v, sizeof v); }
  Writer& F64(double v) { return Raw(&v, sizeof v); }
  Writer& Text(const std::string& s) {
    U32(static_cast<std::uint32_t>(s.size()));
    bytes_.append(s);
    return *this;
  }
  bool Send(int fd) const { return SendAll(fd, bytes_.data(), bytes_.size()); }
  static bool SendAll(int fd, const void* data, std::size_t size) {
    const char* p = static_cast<const char*>(data);
    while (size > 0) {
      const ssize_t n = send(fd, p, size, MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      p += n, size -= static_cast<std::size_t>(n);
    }
    return true;
  }

 private:
  Writer& Raw(const void* p, std::size_t n) {
    bytes_.append(static_cast<const char*>(p), n);
    return *this;
  }
  std::string bytes_;
};

// Reads exactly what is asked, waiting at most until the deadline (none: forever).
class Reader {
 public:
  enum class Status { kOk, kClosed, kTimedOut };
  Reader(int fd, std::optional<double> deadline_ms, const Stopwatch& clock)
      : fd_(fd), deadline_ms_(deadline_ms), clock_(clock) {}

  Status Read(void* data, std::size_t size) {
    char* p = static_cast<char*>(data);
    while (size > 0) {
      int wait_ms = -1;
      if (deadline_ms_) {
        const double left = *deadline_ms_ - clock_.Milliseconds();
        if (left <= 0) return Status::kTimedOut;
        wait_ms = static_cast<int>(left) + 1;
      }
      pollfd ready{.fd = fd_, .events = POLLIN, .revents = 0};
      const int r = poll(&ready, 1, wait_ms);
      if (r < 0 && errno != EINTR) ThrowErrno("poll on the GPU process's socket");
      if (r <= 0) continue;  // interrupted, or the loop's top decides whether time is up
      const ssize_t n = read(fd_, p, size);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return Status::kClosed;
      p += n, size -= static_cast<std::size_t>(n);
    }
    return Status::kOk;
  }
  template <typename T>
  Status Value(T& v) {
    return Read(&v, sizeof v);
  }
  Status Text(std::string& s) {
    std::uint32_t n = 0;
    if (const Status st = Value(n); st != Status::kOk) return st;
    s.resize(n);
    return Read(s.data(), n);
  }

 private:
  int fd_;
  std::optional<double> deadline_ms_;
  const Stopwatch& clock_;
};

void FaultForTests() {
  const char* fault = std::getenv("TWINRASTER_TEST_GPU_FAULT");
  if (!fault) return;
  if (std::strcmp(fault, "abort") == 0) std::abort();
  if (std::strcmp(fault, "hang") == 0) {
    for (;;) pause();
  }
}

// Draws one list and reports it. Returns false when the child cannot go on.
bool ServeList(GpuRenderer& renderer, const DrawList& list, int fd) {
  try {
    FaultForTests();
    Stopwatch clock;
    GpuTimings t;
    const Image image = renderer.Render(list, &t);
    const double work_ms = clock.Milliseconds();
    Writer(kRendered)
        .F64(t.setup_ms).F64(t.draw_ms).F64(t.readback_ms)
        .U64(t.draw_commands).U64(t.instanced_draws)
        .F64(work_ms)
        .U64(image.rgba.size())
        .Send(fd);
    return Writer::SendAll(fd, image.rgba.data(), image.rgba.size());
  } catch (const std::invalid_argument& e) {
    return Writer(kBadList).Text(e.what()).Send(fd);  // nothing was touched: the next list may draw
  } catch (const std::exception& e) {
    Writer(kFailed).Text(e.what()).Send(fd);
    return false;
  }
}

// The child: makes its device, draws the list it was born with, then each list the parent sends
// until the parent closes the socket. Never returns into the parent's code, never flushes the
// parent's buffered output (_exit).
[[noreturn]] void ChildMain(const DrawList& first, const GpuOptions& options, int fd) {
  std::optional<GpuRenderer> renderer;
  try {
    Stopwatch clock;
    renderer.emplace(options);
    const DeviceIdentity& d = renderer->Device();
    Writer(kDevice)
        .Text(d.name).Text(d.driver_name).Text(d.driver_info)
        .U32(d.vendor_id).U32(d.device_id).U32(d.driver_id).U32(d.driver_version).U32(d.api_version).U32(d.subpixel_bits)
        .U32(d.strict_lines ? 1 : 0)
        .F64(clock.Milliseconds())
        .Send(fd);
  } catch (const GpuUnavailable& e) {
    Writer(kUnavailable).Text(e.what()).Send(fd);
    _exit(0);
  } catch (const std::exception& e) {
    Writer(kFailed).Text(e.what()).Send(fd);
    _exit(0);
  }
  if (!ServeList(*renderer, first, fd)) _exit(0);
  const Stopwatch never;
  Reader reader(fd, std::nullopt, never);
  for (;;) {
    std::uint64_t size = 0;
    if (reader.Value(size) != Reader::Status::kOk) _exit(0);  // the parent is done
    std::string bytes(size, '\0');
    if (reader.Read(bytes.data(), size) != Reader::Status::kOk) _exit(0);
    DrawList list;
    try {
      list = gpu::DecodeDrawList(bytes);
    } catch (const std::exception& e) {
      Writer(kFailed).Text(e.what()).Send(fd);
      _exit(0);
    }
    if (!ServeList(*renderer, list, fd)) _exit(0);
  }
}

std::string SignalName(int signal) {
  const char* abbreviation = sigabbrev_np(signal);
  return abbreviation ? std::string("SIG") + abbreviation : "signal " + std::to_string(signal);
}

// Children killed and not yet waited for: tearing a Vulkan device down takes the kernel
// milliseconds, which nobody needs to wait for. Reaped when the next child is made.
std::vector<pid_t>& Unreaped() {
  static std::vector<pid_t> pids;
  return pids;
}

void ReapFinished() {
  std::erase_if(Unreaped(), [](pid_t pid) { return waitpid(pid, nullptr, WNOHANG) == pid; });
}

}  // namespace

struct GpuProcess::Child {
  pid_t pid = -1;
  int fd = -1;
  // Kills without waiting: a child that did its work has nothing more to say.
  ~Child() {
    if (fd >= 0) close(fd);
    if (pid > 0) {
      kill(pid, SIGKILL);
      Unreaped().push_back(pid);
    }
  }
  // Kills (if still running) and waits, for the status that says how it ended.
  int Reap() {
    if (fd >= 0) close(fd), fd = -1;
    kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    pid = -1;
    return status;
  }
};

GpuProcess::GpuProcess(IsolationOptions options) : options_(std::move(options)) {}
GpuProcess::~GpuProcess() = default;

IsolatedGpuResult GpuProcess::Render(const DrawList& list) {
  IsolatedGpuResult result;
  Stopwatch clock;
  // A living child is sent the list; when that fails it has died since, and a fresh one inherits
  // the list instead.
  if (child_) {
    const std::string bytes = gpu::EncodeDrawList(list);
    if (!Writer().U64(bytes.size()).Send(child_->fd) || !Writer::SendAll(child_->fd, bytes.data(), bytes.size())) {
      child_->Reap();
      child_.reset();
    }
  }
  if (!child_) {
    ReapFinished();
    int fds[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) ThrowErrno("socketpair for the GPU process");
    const pid_t pid = fork();
    if (pid < 0) {
      close(fds[0]), close(fds[1]);
      ThrowErrno("fork of the GPU process");
    }
    if (pid == 0) {
      close(fds[0]);
      ChildMain(list, options_.gpu, fds[1]);
    }
    close(fds[1]);
    child_ = std::make_unique<Child>();
    child_->pid = pid, child_->fd = fds[0];
    device_ = DeviceIdentity{};
  }
  // Faulted in now, while the child works, rather than after.
  Image image(list.width, list.height);

  std::optional<double> deadline;
  if (options_.timeout_seconds > 0) deadline = clock.Milliseconds() + options_.timeout_seconds * 1000.0;
  Reader reader(child_->fd, deadline, clock);
  using Status = Reader::Status;
  Status status = Status::kOk;
  double work_ms = 0;
  bool done = false, child_goes_on = false;
  while (!done && status == Status::kOk) {
    char tag = 0;
    if ((status = reader.Value(tag)) != Status::kOk) break;
    if (tag == kDevice) {
      DeviceIdentity& d = device_;
      std::uint32_t* numbers[] = {&d.vendor_id, &d.device_id, &d.driver_id, &d.driver_version, &d.api_version, &d.subpixel_bits};
      for (std::string* text : {&d.name, &d.driver_name, &d.driver_info}) {
        if (status == Status::kOk) status = reader.Text(*text);
      }
      for (std::uint32_t* number : numbers) {
        if (status == Status::kOk) status = reader.Value(*number);
      }
      std::uint32_t strict_lines = 0;
      if (status == Status::kOk) status = reader.Value(strict_lines);
      d.strict_lines = strict_lines != 0;
      if (status == Status::kOk) status = reader.Value(result.device_ms);
    } else if (tag == kRendered) {
      GpuTimings& t = result.timings;
      std::uint64_t draws = 0, instanced = 0, size = 0;
      for (double* v : {&t.setup_ms, &t.draw_ms, &t.readback_ms}) {
        if (status == Status::kOk) status = reader.Value(*v);
      }
      for (std::uint64_t* v : {&draws, &instanced}) {
        if (status == Status::kOk) status = reader.Value(*v);
      }
      if (status == Status::kOk) status = reader.Value(work_ms);
      if (status == Status::kOk) status = reader.Value(size);
      if (status == Status::kOk && size != image.rgba.size()) throw std::logic_error("GPU process: pixels of the wrong size");
      if (status == Status::kOk) status = reader.Read(image.rgba.data(), image.rgba.size());
      t.draw_commands = draws, t.instanced_draws = instanced;
      result.outcome = GpuOutcome::kRendered;
      done = child_goes_on = status == Status::kOk;
    } else if (tag == kUnavailable || tag == kBadList || tag == kFailed) {
      status = reader.Text(result.problem);
      result.outcome = tag == kUnavailable ? GpuOutcome::kUnavailable
                       : tag == kBadList   ? GpuOutcome::kBadList
                                           : GpuOutcome::kCrashed;
      done = status == Status::kOk;
      child_goes_on = tag == kBadList;
    } else {
      throw std::logic_error("GPU process: unknown message");
    }
  }
  result.device = device_;

  if (done) {
    if (!child_goes_on) child_.reset();
    if (result.outcome == GpuOutcome::kRendered) {
      result.image = std::move(image);
      result.isolation_ms = std::max(0.0, clock.Milliseconds() - result.device_ms - work_ms);
    }
    return result;
  }
  // Closed before a whole answer, or out of time.
  const int exit_status = child_->Reap();
  child_.reset();
  result.image = Image{};
  if (status == Status::kTimedOut) {
    result.outcome = GpuOutcome::kTimedOut;
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", options_.timeout_seconds);
    result.problem = std::string("timed out after ") + seconds + " s";
  } else if (WIFSIGNALED(exit_status)) {
    result.outcome = GpuOutcome::kCrashed;
    result.signal = SignalName(WTERMSIG(exit_status));
    result.problem = "the Vulkan driver crashed (" + result.signal + ")";
  } else {
    result.outcome = GpuOutcome::kCrashed;
    result.problem = "the GPU process exited (status " + std::to_string(WEXITSTATUS(exit_status)) + ") without a result";
  }
  return result;
}

IsolatedGpuResult RenderIsolated(const DrawList& list, const IsolationOptions& options) {
  GpuProcess process(options);
  return process.Render(list);
}

}  // namespace twinraster
