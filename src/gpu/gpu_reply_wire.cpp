#include "gpu/gpu_reply_wire.hpp"

#include <stdexcept>
#include <type_traits>

namespace twinraster::gpu {
namespace {

// Appends a message to `bytes`, which the caller returns as it is (a string moved out of a member
// trips GCC 12's -Warray-bounds on its short-string buffer).
class Encoder {
 public:
  Encoder(std::string& bytes, ReplyTag tag) : bytes_(bytes) { bytes_.push_back(static_cast<char>(tag)); }
  template <typename T>
  void Value(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void Count(std::size_t n) { Value(std::uint64_t{n}); }
  void Flag(bool flag) { Value(std::uint32_t{flag ? 1u : 0u}); }
  void Text(std::string_view text) {
    Value(static_cast<std::uint32_t>(text.size()));
    bytes_.append(text);
  }

 private:
  std::string& bytes_;
};

// Reads until the first read that fails, then nothing more: its status is the message's.
class Decoder {
 public:
  explicit Decoder(ByteSource& in) : in_(in) {}
  void Bytes(void* data, std::size_t size) {
    if (status_ == ReadStatus::kOk) status_ = in_.Read(data, size);
  }
  template <typename T>
  void Value(T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    Bytes(&value, sizeof value);
  }
  void Count(std::size_t& n) {
    std::uint64_t wide = 0;
    Value(wide);
    n = wide;
  }
  void Flag(bool& flag) {
    std::uint32_t word = 0;
    Value(word);
    flag = word != 0;
  }
  void Text(std::string& text) {
    std::uint32_t size = 0;
    Value(size);
    if (status_ != ReadStatus::kOk) return;
    text.resize(size);
    Bytes(text.data(), size);
  }
  ReadStatus status() const { return status_; }

 private:
  ByteSource& in_;
  ReadStatus status_ = ReadStatus::kOk;
};

// One walk over each message's fields, for both directions: what is written is what is read.
template <typename Coder, typename Reply>
void WalkDevice(Coder& c, Reply& reply) {
  auto& d = reply.device;
  c.Text(d.name), c.Text(d.driver_name), c.Text(d.driver_info);
  c.Value(d.vendor_id), c.Value(d.device_id), c.Value(d.driver_id), c.Value(d.driver_version);
  c.Value(d.api_version), c.Value(d.subpixel_bits);
  c.Flag(d.strict_lines);
  c.Value(reply.device_ms);
}

template <typename Coder, typename Reply>
void WalkRendered(Coder& c, Reply& reply) {
  auto& t = reply.timings;
  c.Value(t.setup_ms), c.Value(t.draw_ms), c.Value(t.readback_ms);
  c.Count(t.draw_commands), c.Count(t.instanced_draws);
  c.Value(reply.work_ms);
  c.Value(reply.pixel_bytes);
}

}  // namespace

ReadStatus ReadTag(ByteSource& in, ReplyTag& tag) {
  char byte = 0;
  const ReadStatus status = in.Read(&byte, 1);
  if (status != ReadStatus::kOk) return status;
  switch (static_cast<ReplyTag>(byte)) {
    case ReplyTag::kDevice:
    case ReplyTag::kRendered:
    case ReplyTag::kUnavailable:
    case ReplyTag::kBadList:
    case ReplyTag::kFailed: tag = static_cast<ReplyTag>(byte); return status;
  }
  throw std::logic_error("GPU process: unknown message");
}

std::string EncodeDevice(const DeviceReply& reply) {
  std::string bytes;
  Encoder e(bytes, ReplyTag::kDevice);
  WalkDevice(e, reply);
  return bytes;
}

ReadStatus ReadDevice(ByteSource& in, DeviceReply& reply) {
  Decoder d(in);
  WalkDevice(d, reply);
  return d.status();
}

std::string EncodeRendered(const RenderedReply& reply) {
  std::string bytes;
  Encoder e(bytes, ReplyTag::kRendered);
  WalkRendered(e, reply);
  return bytes;
}

ReadStatus ReadRendered(ByteSource& in, RenderedReply& reply, std::span<std::uint8_t> pixels) {
  Decoder d(in);
  WalkRendered(d, reply);
  if (d.status() == ReadStatus::kOk && reply.pixel_bytes != pixels.size()) {
    throw std::logic_error("GPU process: pixels of the wrong size");
  }
  d.Bytes(pixels.data(), pixels.size());
  return d.status();
}

std::string EncodeProblem(ReplyTag tag, std::string_view problem) {
  std::string bytes;
  Encoder(bytes, tag).Text(problem);
  return bytes;
}

ReadStatus ReadProblem(ByteSource& in, std::string& problem) {
  Decoder d(in);
  d.Text(problem);
  return d.status();
}

}  // namespace twinraster::gpu
