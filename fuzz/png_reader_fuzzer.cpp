// libFuzzer target for the image path `verify` takes with a file from anywhere: bytes, then the PNG
// reader (DecodePng, with the canvas checked before decoding, as verify does), then the verifier on
// a small shipped scene (scenes/cgfs-transforms.json drawn at 64 x 64, filled or as a wireframe, at
// 4 to 8 subpixel bits, strict lines or not: chosen by the input's last byte), then the map. A
// refusal is a FileError with a message that names the input and holds no control character;
// anything else (another exception, a crash, a leak, undefined behaviour, a hang, memory past the
// limit) is a finding.
#include "chain/draw_list.hpp"
#include "files/png_file.hpp"
#include "files/staged_file.hpp"
#include "scene/scene_loader.hpp"
#include "verify/verifier.hpp"
#include "verify/verify_map.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace {

// The canvas every seed in scripts/fuzz.sh is rendered at.
constexpr std::uint32_t kCanvas = 64;

struct Drawn {
  twinraster::Scene scene;
  twinraster::DrawList list;
};

Drawn SmallScene(bool wireframe) {
  twinraster::Scene scene =
      twinraster::LoadScene(std::filesystem::path(TWINRASTER_SOURCE_DIR) / "scenes/cgfs-transforms.json");
  scene.canvas.width = scene.canvas.height = kCanvas;
  scene.wireframe = wireframe;
  twinraster::DrawList list = twinraster::BuildDrawList(scene);
  return {std::move(scene), std::move(list)};
}

void Check(bool promise) {
  if (!promise) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Drawn filled = SmallScene(false), wireframe = SmallScene(true);
  const std::uint8_t last = size > 0 ? data[size - 1] : 0;
  const Drawn& drawn = (last & 16) != 0 ? wireframe : filled;
  twinraster::Image image;
  try {
    image = twinraster::files::DecodePng(std::string_view(reinterpret_cast<const char*>(data), size), "input",
                                         [](std::uint32_t width, std::uint32_t height) {
                                           if (width != kCanvas || height != kCanvas)
                                             throw twinraster::files::FileError("input: not 64 x 64");
                                         });
  } catch (const twinraster::files::FileError& e) {
    const std::string message = e.what();
    Check(message.starts_with("input: "));
    Check(std::none_of(message.begin(), message.end(),
                       [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }));
    return 0;
  }
  Check(image.width == kCanvas && image.height == kCanvas && image.rgba.size() == std::size_t{kCanvas} * kCanvas * 4);
  const twinraster::verify::VerifyOptions options{.subpixel_bits = 4 + last % 5, .strict_lines = (last & 8) != 0};
  const twinraster::verify::Verification v = twinraster::verify::VerifyImage(drawn.scene, drawn.list, image, options);
  const twinraster::Image map = twinraster::verify::VerificationMap(image, v);
  Check(map.width == image.width && map.height == image.height);
  return 0;
}
