// The GPU process's replies: each message read back is the message written, a reply cut short
// says so, and a byte that is no tag or pixels of the wrong size are refused.
#include "gpu/gpu_reply_wire.hpp"

#include "support/catch.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

using namespace twinraster;
using namespace twinraster::gpu;

namespace {

// Replies from memory, as the socket would give them; past the end, the peer has closed.
class StringSource final : public ByteSource {
 public:
  explicit StringSource(std::string bytes) : bytes_(std::move(bytes)) {}
  ReadStatus Read(void* data, std::size_t size) override {
    if (bytes_.size() - at_ < size) {
      at_ = bytes_.size();
      return ReadStatus::kClosed;
    }
    if (size > 0) std::memcpy(data, bytes_.data() + at_, size);
    at_ += size;
    return ReadStatus::kOk;
  }
  bool Done() const { return at_ == bytes_.size(); }

 private:
  std::string bytes_;
  std::size_t at_ = 0;
};

DeviceReply SomeDevice() {
  DeviceReply reply;
  gpu::DeviceIdentity& d = reply.device;
  d.name = "llvmpipe (LLVM 15.0.6, 256 bits)", d.driver_name = "llvmpipe", d.driver_info = "";
  d.vendor_id = 0x10005, d.device_id = 7, d.driver_id = 13, d.driver_version = 0x5803006;
  d.api_version = 0x403105, d.subpixel_bits = 8, d.strict_lines = true;
  reply.device_ms = 41.25;
  return reply;
}

RenderedReply SomeRendered(std::size_t pixel_bytes) {
  const gpu::GpuTimings timings{
      .setup_ms = 1.5, .draw_ms = 2.25, .readback_ms = 0.125, .draw_commands = 300, .instanced_draws = 9};
  return {.timings = timings, .work_ms = 4.5, .pixel_bytes = pixel_bytes};
}

}  // namespace

TEST_CASE("A device reply reads back as written") {
  const DeviceReply sent = SomeDevice();
  StringSource in(EncodeDevice(sent));
  ReplyTag tag{};
  REQUIRE(ReadTag(in, tag) == ReadStatus::kOk);
  CHECK(tag == ReplyTag::kDevice);
  DeviceReply got;
  REQUIRE(ReadDevice(in, got) == ReadStatus::kOk);
  CHECK(in.Done());
  CHECK(got.device.name == sent.device.name);
  CHECK(got.device.driver_name == sent.device.driver_name);
  CHECK(got.device.driver_info.empty());
  CHECK(got.device.vendor_id == sent.device.vendor_id);
  CHECK(got.device.device_id == sent.device.device_id);
  CHECK(got.device.driver_id == sent.device.driver_id);
  CHECK(got.device.driver_version == sent.device.driver_version);
  CHECK(got.device.api_version == sent.device.api_version);
  CHECK(got.device.subpixel_bits == sent.device.subpixel_bits);
  CHECK(got.device.strict_lines);
  CHECK(got.device_ms == sent.device_ms);
}

TEST_CASE("A device without strict lines reads back without them") {
  DeviceReply sent = SomeDevice();
  sent.device.strict_lines = false;
  StringSource in(EncodeDevice(sent));
  ReplyTag tag{};
  REQUIRE(ReadTag(in, tag) == ReadStatus::kOk);
  DeviceReply got;
  got.device.strict_lines = true;
  REQUIRE(ReadDevice(in, got) == ReadStatus::kOk);
  CHECK_FALSE(got.device.strict_lines);
}

TEST_CASE("A rendered reply reads back with its pixels") {
  const std::vector<std::uint8_t> pixels = {1, 2, 3, 255, 4, 5, 6, 255};
  const RenderedReply sent = SomeRendered(pixels.size());
  StringSource in(EncodeRendered(sent) + std::string(pixels.begin(), pixels.end()));
  ReplyTag tag{};
  REQUIRE(ReadTag(in, tag) == ReadStatus::kOk);
  CHECK(tag == ReplyTag::kRendered);
  RenderedReply got;
  std::vector<std::uint8_t> image(pixels.size(), 0);
  REQUIRE(ReadRendered(in, got, image) == ReadStatus::kOk);
  CHECK(in.Done());
  CHECK(image == pixels);
  CHECK(got.timings.setup_ms == sent.timings.setup_ms);
  CHECK(got.timings.draw_ms == sent.timings.draw_ms);
  CHECK(got.timings.readback_ms == sent.timings.readback_ms);
  CHECK(got.timings.draw_commands == sent.timings.draw_commands);
  CHECK(got.timings.instanced_draws == sent.timings.instanced_draws);
  CHECK(got.work_ms == sent.work_ms);
  CHECK(got.pixel_bytes == pixels.size());
}

TEST_CASE("Pixels of another size than the image's are refused") {
  StringSource in(EncodeRendered(SomeRendered(8)) + std::string(8, '\x7f'));
  ReplyTag tag{};
  REQUIRE(ReadTag(in, tag) == ReadStatus::kOk);
  RenderedReply got;
  std::vector<std::uint8_t> image(4, 0);
  CHECK_THROWS_AS(ReadRendered(in, got, image), std::logic_error);
}

TEST_CASE("Each problem reply reads back with its tag and words") {
  for (const ReplyTag sent_tag : {ReplyTag::kUnavailable, ReplyTag::kBadList, ReplyTag::kFailed}) {
    StringSource in(EncodeProblem(sent_tag, "draw 3: mesh 7 out of range"));
    ReplyTag tag{};
    REQUIRE(ReadTag(in, tag) == ReadStatus::kOk);
    CHECK(tag == sent_tag);
    std::string problem;
    REQUIRE(ReadProblem(in, problem) == ReadStatus::kOk);
    CHECK(in.Done());
    CHECK(problem == "draw 3: mesh 7 out of range");
  }
}

TEST_CASE("Replies follow one another on the stream") {
  StringSource in(EncodeDevice(SomeDevice()) + EncodeProblem(ReplyTag::kBadList, "no"));
  ReplyTag tag{};
  DeviceReply device;
  std::string problem;
  REQUIRE(ReadTag(in, tag) == ReadStatus::kOk);
  REQUIRE(ReadDevice(in, device) == ReadStatus::kOk);
  REQUIRE(ReadTag(in, tag) == ReadStatus::kOk);
  CHECK(tag == ReplyTag::kBadList);
  REQUIRE(ReadProblem(in, problem) == ReadStatus::kOk);
  CHECK(problem == "no");
  CHECK(in.Done());
}

TEST_CASE("A reply cut anywhere reads as closed, with the fields before the cut") {
  const DeviceReply sent = SomeDevice();
  const std::string whole = EncodeDevice(sent);
  for (std::size_t cut = 1; cut < whole.size(); ++cut) {
    StringSource in(whole.substr(0, cut));
    ReplyTag tag{};
    REQUIRE(ReadTag(in, tag) == ReadStatus::kOk);
    DeviceReply got;
    CHECK(ReadDevice(in, got) == ReadStatus::kClosed);
    CHECK(got.device_ms == 0);  // the last field
  }
  // The name, the first field, is whole once its length and bytes are in.
  const std::size_t after_name = 1 + 4 + sent.device.name.size();
  StringSource in(whole.substr(0, after_name));
  ReplyTag tag{};
  REQUIRE(ReadTag(in, tag) == ReadStatus::kOk);
  DeviceReply got;
  CHECK(ReadDevice(in, got) == ReadStatus::kClosed);
  CHECK(got.device.name == sent.device.name);
  CHECK(got.device.driver_name.empty());
}

TEST_CASE("Pixels cut short read as closed") {
  const std::string message = EncodeRendered(SomeRendered(8)) + std::string(5, '\x01');
  StringSource in(message);
  ReplyTag tag{};
  REQUIRE(ReadTag(in, tag) == ReadStatus::kOk);
  RenderedReply got;
  std::vector<std::uint8_t> image(8, 0);
  CHECK(ReadRendered(in, got, image) == ReadStatus::kClosed);
  CHECK(got.timings.draw_commands == 300);
}

TEST_CASE("A byte that is no reply's tag is refused") {
  StringSource in("Z");
  ReplyTag tag{};
  CHECK_THROWS_AS(ReadTag(in, tag), std::logic_error);
}

TEST_CASE("Nothing at all reads as closed") {
  StringSource in("");
  ReplyTag tag{};
  CHECK(ReadTag(in, tag) == ReadStatus::kClosed);
}

TEST_CASE("The bytes of a device reply: the tag, then the fields in order, numbers as they lie") {
  const std::string bytes = EncodeDevice(SomeDevice());
  CHECK(bytes.front() == 'D');
  std::uint32_t name_size = 0;
  std::memcpy(&name_size, bytes.data() + 1, sizeof name_size);
  CHECK(name_size == SomeDevice().device.name.size());
  // Three texts, seven 32-bit numbers (strict lines as one of them), one double.
  const gpu::DeviceIdentity& d = SomeDevice().device;
  CHECK(bytes.size() == 1 + 3 * 4 + d.name.size() + d.driver_name.size() + d.driver_info.size() + 7 * 4 + 8);
  CHECK(EncodeRendered(SomeRendered(0)).size() == 1 + 3 * 8 + 2 * 8 + 8 + 8);
  std::string problem = "X";
  const std::uint32_t size = 3;
  problem.append(reinterpret_cast<const char*>(&size), sizeof size);
  CHECK(EncodeProblem(ReplyTag::kFailed, "abc") == problem + "abc");
}
