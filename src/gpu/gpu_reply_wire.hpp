// The GPU process's replies (child to parent, gpu/isolated_gpu.hpp) as bytes and back: each
// message's writer and reader are one walk over its fields, so both ends agree on their order.
// It neither sends nor waits: the caller writes the bytes to the socket, and reads through a
// ByteSource that knows the socket and the time limit. Both ends are the same executable, so
// numbers go as they lie in memory.
#pragma once

#include "gpu/gpu_renderer.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace twinraster::gpu {

// The first byte of every reply. The child sends kDevice once it has its device, then for each
// list kRendered (followed by the pixels) or one of the problems.
enum class ReplyTag : char { kDevice = 'D', kRendered = 'R', kUnavailable = 'U', kBadList = 'B', kFailed = 'X' };

enum class ReadStatus { kOk, kClosed, kTimedOut };

// Where the parent reads replies from: Read fills exactly `size` bytes, or says why it could not.
class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual ReadStatus Read(void* data, std::size_t size) = 0;
};

// Throws std::logic_error for a byte that is no ReplyTag.
ReadStatus ReadTag(ByteSource& in, ReplyTag& tag);

// The Read* functions read what follows the tag. On a status other than kOk the fields read so far
// are set and the rest keep what they held.

// kDevice. DeviceIdentity::line_rasterization is not sent: it is the same for every device.
struct DeviceReply {
  DeviceIdentity device;
  double device_ms = 0;  // making the instance, the device and the pipelines
};
std::string EncodeDevice(const DeviceReply& reply);
ReadStatus ReadDevice(ByteSource& in, DeviceReply& reply);

// kRendered. The message ends before the pixels: they are sent after it as they lie in the Image,
// and read straight into one.
struct RenderedReply {
  GpuTimings timings;
  double work_ms = 0;             // the child's wall time for the list, from taking it to its pixels
  std::uint64_t pixel_bytes = 0;  // the RGBA bytes that follow
};
std::string EncodeRendered(const RenderedReply& reply);
// Reads the message and then the pixels into `pixels`; throws std::logic_error when pixel_bytes is
// not pixels.size().
ReadStatus ReadRendered(ByteSource& in, RenderedReply& reply, std::span<std::uint8_t> pixels);

// kUnavailable, kBadList or kFailed: what went wrong, in words.
std::string EncodeProblem(ReplyTag tag, std::string_view problem);
ReadStatus ReadProblem(ByteSource& in, std::string& problem);

}  // namespace twinraster::gpu
