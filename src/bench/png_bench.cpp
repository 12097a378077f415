#include "bench/png_bench.hpp"

#include "base/stopwatch.hpp"
#include "bench/bench_suite.hpp"
#include "files/png_file.hpp"

#include <stb/stb_image_write.h>

#include <functional>
#include <stdexcept>

namespace twinraster::bench {

namespace {

// stb_image_write at its defaults (level 8 of its own deflate, all five filters tried per row),
// the file collected in memory as its callback hands it over.
std::size_t StbPngBytes(const Image& image) {
  std::string png;
  const auto collect = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (stbi_write_png_to_func(collect, &png, static_cast<int>(image.width), static_cast<int>(image.height), 4,
                             image.rgba.data(), static_cast<int>(image.width) * 4) == 0) {
    throw std::runtime_error("stb_image_write could not encode the frame");
  }
  return png.size();
}

struct Encoder {
  const char* name;
  std::function<std::size_t(const Image&)> encode;  // the file's size
};

std::vector<Encoder> Encoders() {
  const auto libdeflate = [](int level) {
    return [level](const Image& image) { return files::EncodePngWithLibdeflate(image, level).size(); };
  };
  return {
      {"runs (level 1, the default)", [](const Image& image) { return files::EncodePng(image).size(); }},
      {"libdeflate 0 (stored)", libdeflate(0)},
      {"libdeflate 1", libdeflate(1)},
      {"libdeflate 6", libdeflate(6)},
      {"stb_image_write", StbPngBytes},
  };
}

}  // namespace

std::vector<PngEncoding> ComparePngEncoders(const Image& image, int runs) {
  const std::vector<Encoder> encoders = Encoders();
  std::vector<std::vector<double>> times(encoders.size());
  std::vector<PngEncoding> result(encoders.size());
  for (int run = 0; run < runs; ++run) {
    for (std::size_t e = 0; e < encoders.size(); ++e) {
      Stopwatch clock;
      result[e].bytes = encoders[e].encode(image);
      times[e].push_back(clock.Milliseconds());
    }
  }
  for (std::size_t e = 0; e < encoders.size(); ++e) {
    result[e].encoder = encoders[e].name;
    result[e].ms = Median(times[e]);
  }
  return result;
}

}  // namespace twinraster::bench
