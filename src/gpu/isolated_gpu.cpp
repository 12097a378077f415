#include "gpu/isolated_gpu.hpp"

#include "base/stopwatch.hpp"
#include "gpu/draw_list_wire.hpp"
#include "gpu/gpu_reply_wire.hpp"

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

namespace twinraster::gpu {
namespace {

[[noreturn]] void ThrowErrno(const char* what) { throw std::system_error(errno, std::generic_category(), what); }

// MSG_NOSIGNAL: a peer that died is an error to report, not a SIGPIPE that would kill the writer.
bool SendAll(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = send(fd, p, size, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n, size -= static_cast<std::size_t>(n);
  }
  return true;
}

bool SendAll(int fd, const std::string& bytes) { return SendAll(fd, bytes.data(), bytes.size()); }

// The parent's request: the encoded list's length, then the list.
bool SendList(int fd, const std::string& bytes) {
  const std::uint64_t size = bytes.size();
  return SendAll(fd, &size, sizeof size) && SendAll(fd, bytes);
}

// Reads exactly what is asked from a stream socket, waiting at most until the deadline (none:
// forever).
class SocketReader final : public ByteSource {
 public:
  SocketReader(int fd, std::optional<double> deadline_ms, const Stopwatch& clock)
      : fd_(fd), deadline_ms_(deadline_ms), clock_(clock) {}

  ReadStatus Read(void* data, std::size_t size) override {
    char* p = static_cast<char*>(data);
    while (size > 0) {
      int wait_ms = -1;
      if (deadline_ms_) {
        const double left = *deadline_ms_ - clock_.Milliseconds();
        if (left <= 0) return ReadStatus::kTimedOut;
        wait_ms = static_cast<int>(left) + 1;
      }
      pollfd ready{.fd = fd_, .events = POLLIN, .revents = 0};
      const int r = poll(&ready, 1, wait_ms);
      if (r < 0 && errno != EINTR) ThrowErrno("poll on the GPU process's socket");
      if (r <= 0) continue;  // interrupted, or the loop's top decides whether time is up
      const ssize_t n = read(fd_, p, size);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return ReadStatus::kClosed;
      p += n, size -= static_cast<std::size_t>(n);
    }
    return ReadStatus::kOk;
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
    RenderedReply reply;
    const Image image = renderer.Render(list, &reply.timings);
    reply.work_ms = clock.Milliseconds();
    reply.pixel_bytes = image.rgba.size();
    SendAll(fd, EncodeRendered(reply));
    return SendAll(fd, image.rgba.data(), image.rgba.size());
  } catch (const std::invalid_argument& e) {
    // Nothing was touched: the next list may draw.
    return SendAll(fd, EncodeProblem(ReplyTag::kBadList, e.what()));
  } catch (const std::exception& e) {
    SendAll(fd, EncodeProblem(ReplyTag::kFailed, e.what()));
    return false;
  }
}

// Makes the child's renderer and tells the parent its device; false, with the reason sent instead,
// when it cannot be made.
bool MakeRenderer(std::optional<GpuRenderer>& renderer, const GpuOptions& options, int fd) {
  try {
    Stopwatch clock;
    renderer.emplace(options);
    SendAll(fd, EncodeDevice({.device = renderer->Device(), .device_ms = clock.Milliseconds()}));
    return true;
  } catch (const GpuUnavailable& e) {
    SendAll(fd, EncodeProblem(ReplyTag::kUnavailable, e.what()));
  } catch (const std::exception& e) {
    SendAll(fd, EncodeProblem(ReplyTag::kFailed, e.what()));
  }
  return false;
}

// The child: makes its device, draws the list it was born with, then each list the parent sends
// until the parent closes the socket. Never returns into the parent's code, never flushes the
// parent's buffered output (_exit).
[[noreturn]] void ChildMain(const DrawList& first, const GpuOptions& options, int fd) {
  std::optional<GpuRenderer> renderer;
  if (!MakeRenderer(renderer, options, fd) || !ServeList(*renderer, first, fd)) _exit(0);
  const Stopwatch never;
  SocketReader reader(fd, std::nullopt, never);
  for (;;) {
    std::uint64_t size = 0;
    if (reader.Read(&size, sizeof size) != ReadStatus::kOk) _exit(0);  // the parent is done
    std::string bytes(size, '\0');
    if (reader.Read(bytes.data(), size) != ReadStatus::kOk) _exit(0);
    DrawList list;
    try {
      list = DecodeDrawList(bytes);
    } catch (const std::exception& e) {
      SendAll(fd, EncodeProblem(ReplyTag::kFailed, e.what()));
      _exit(0);
    }
    if (!ServeList(*renderer, list, fd)) _exit(0);
  }
}

// How the child answered one list.
struct Answer {
  ReadStatus status = ReadStatus::kOk;  // kOk: a whole answer came
  bool child_goes_on = false;           // it takes the next list
  double work_ms = 0;                   // the list's time as the child measured it
};

// Reads replies until one answers the list: the pixels into `image`, a fresh child's device (its
// first reply) into `device`, the rest into `result`.
Answer Await(ByteSource& in, DeviceIdentity& device, Image& image, IsolatedGpuResult& result) {
  Answer answer;
  for (;;) {
    ReplyTag tag{};
    if ((answer.status = ReadTag(in, tag)) != ReadStatus::kOk) return answer;
    if (tag == ReplyTag::kDevice) {
      DeviceReply reply;
      answer.status = ReadDevice(in, reply);
      device = reply.device, result.device_ms = reply.device_ms;
      if (answer.status != ReadStatus::kOk) return answer;
    } else if (tag == ReplyTag::kRendered) {
      RenderedReply reply;
      answer.status = ReadRendered(in, reply, image.rgba);
      result.timings = reply.timings, answer.work_ms = reply.work_ms;
      result.outcome = GpuOutcome::kRendered;
      answer.child_goes_on = answer.status == ReadStatus::kOk;
      return answer;
    } else {
      answer.status = ReadProblem(in, result.problem);
      result.outcome = tag == ReplyTag::kUnavailable ? GpuOutcome::kUnavailable
                       : tag == ReplyTag::kBadList   ? GpuOutcome::kBadList
                                                     : GpuOutcome::kCrashed;
      answer.child_goes_on = tag == ReplyTag::kBadList;
      return answer;
    }
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
  Submit(list);
  return Collect();
}

void GpuProcess::Submit(const DrawList& list) {
  if (pending_) throw std::logic_error("GpuProcess::Submit: the last list was not collected");
  Stopwatch clock;
  Hand(list);
  pending_ = Pending{clock, clock.Milliseconds(), list.width, list.height};
}

IsolatedGpuResult GpuProcess::Collect() {
  if (!pending_) throw std::logic_error("GpuProcess::Collect: no list was submitted");
  const Pending pending = *pending_;
  pending_.reset();
  const double away_ms = pending.clock.Milliseconds() - pending.submit_ms;  // this process's own work
  const Stopwatch collect_clock;
  IsolatedGpuResult result;
  // Faulted in now, while the child works, rather than after.
  Image image(pending.width, pending.height);
  std::optional<double> deadline;
  if (options_.timeout_seconds > 0) deadline = pending.clock.Milliseconds() + options_.timeout_seconds * 1000.0;
  SocketReader reader(child_->fd, deadline, pending.clock);
  const Answer answer = Await(reader, device_, image, result);
  result.device = device_;
  if (answer.status != ReadStatus::kOk) {
    ReapLost(answer.status == ReadStatus::kTimedOut, result);
    return result;
  }
  if (!answer.child_goes_on) child_.reset();
  if (result.outcome == GpuOutcome::kRendered) {
    result.image = std::move(image);
    // The wait for what the child still had to do once this process came back is not overhead.
    const double still_working_ms = std::max(0.0, result.device_ms + answer.work_ms - away_ms);
    result.isolation_ms = pending.submit_ms + std::max(0.0, collect_clock.Milliseconds() - still_working_ms);
  }
  return result;
}

// A living child is sent the list; when that fails it has died since, and a fresh one inherits the
// list instead.
void GpuProcess::Hand(const DrawList& list) {
  if (child_ && !SendList(child_->fd, EncodeDrawList(list))) {
    child_->Reap();
    child_.reset();
  }
  if (!child_) Spawn(list);
}

void GpuProcess::Spawn(const DrawList& list) {
  ReapFinished();
  int fds[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) ThrowErrno("socketpair for the GPU process");
  if (options_.before_fork) options_.before_fork();
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

// The child closed the socket before a whole answer, or ran out of time: it is reaped, and how it
// ended is the result.
void GpuProcess::ReapLost(bool timed_out, IsolatedGpuResult& result) {
  const int exit_status = child_->Reap();
  child_.reset();
  result.image = Image{};
  if (timed_out) {
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
    result.problem =
        "the GPU process exited (status " + std::to_string(WEXITSTATUS(exit_status)) + ") without a result";
  }
}

IsolatedGpuResult RenderIsolated(const DrawList& list, const IsolationOptions& options) {
  GpuProcess process(options);
  return process.Render(list);
}

}  // namespace twinraster::gpu
