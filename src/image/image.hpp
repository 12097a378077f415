// An 8-bit RGBA image in memory, top row first: what every renderer produces and every PNG holds.
#pragma once

#include "image/frame_memory.hpp"

#include <cstddef>
#include <cstdint>

namespace twinraster {

struct Image {
  std::uint32_t width = 0, height = 0;
  FrameVector<std::uint8_t> rgba;  // width * height * 4 bytes, row y starts at y * width * 4

  // For a renderer that writes every pixel itself: the image's bytes are left uninitialized.
  struct Uncleared {};

  Image() = default;
  Image(std::uint32_t w, std::uint32_t h) : width(w), height(h), rgba(std::size_t{w} * h * 4, 0) {}
  Image(std::uint32_t w, std::uint32_t h, Uncleared) : width(w), height(h), rgba(std::size_t{w} * h * 4) {}

  std::uint8_t* pixel(std::uint32_t x, std::uint32_t y) { return &rgba[(std::size_t{y} * width + x) * 4]; }
  const std::uint8_t* pixel(std::uint32_t x, std::uint32_t y) const { return &rgba[(std::size_t{y} * width + x) * 4]; }
};

// Pixels whose alpha is not 255: what `verify`, which judges colour and not alpha, reports.
inline std::uint64_t NotOpaquePixels(const Image& image) {
  std::uint64_t n = 0;
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) n += image.rgba[i] != 255;
  return n;
}

}  // namespace twinraster
