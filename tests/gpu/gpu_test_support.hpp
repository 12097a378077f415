// Hand-made draw lists and a pixel checker for the GPU tests: triangles are given in window
// pixels, so the expected image can be worked out by hand (or by the edge test below).
#pragma once

#include "chain/draw_list.hpp"
#include "image/image.hpp"
#include "support/chapter_cube.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace twinraster {

inline std::ostream& operator<<(std::ostream& out, const Rgb8& c) {
  return out << "(" << int{c.r} << ", " << int{c.g} << ", " << int{c.b} << ")";
}

namespace gpu_test {

// Sets an environment variable for one scope (the loader, the layer and lavapipe read theirs
// when a renderer is created); assumes it was unset before.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) { setenv(name, value, 1); }
  ~ScopedEnv() { unsetenv(name_); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
};

// A triangle in window coordinates (pixels, y down, pixel centres at +0.5) with its colour.
struct WindowTriangle {
  glm::dvec2 a, b, c;
  Rgb8 colour;
};

// Window pixels to clip space for F = identity: x_ndc = 2x / width - 1 (exact for power-of-two
// sizes).
inline glm::vec3 ToNdc(glm::dvec2 window, std::uint32_t width, std::uint32_t height, float z) {
  return glm::vec3(static_cast<float>(2.0 * window.x / width - 1.0), static_cast<float>(2.0 * window.y / height - 1.0),
                   z);
}

// A mesh of separate triangles at depth z, placed with F = identity.
inline DrawMesh MeshOf(const std::vector<WindowTriangle>& triangles, std::uint32_t width, std::uint32_t height,
                       float z = 0.5f) {
  DrawMesh mesh;
  for (const WindowTriangle& t : triangles) {
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    for (const glm::dvec2& corner : {t.a, t.b, t.c}) mesh.positions.push_back(ToNdc(corner, width, height, z));
    mesh.triangles.push_back({first, first + 1, first + 2});
    mesh.colours.push_back(t.colour);
  }
  return mesh;
}

inline glm::mat4 Translation(float x, float y, float z) {
  glm::mat4 m(1.0f);
  m[3] = glm::vec4(x, y, z, 1.0f);
  return m;
}

inline Rgb8 RgbAt(const Image& image, std::uint32_t x, std::uint32_t y) {
  const std::uint8_t* p = image.pixel(x, y);
  return Rgb8{p[0], p[1], p[2]};
}

inline std::size_t CountColour(const Image& image, Rgb8 colour) {
  std::size_t count = 0;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x) count += RgbAt(image, x, y) == colour;
  return count;
}

// Where a pixel centre lies: +1 inside the triangle by more than a subpixel (1/256 px) from
// every edge, -1 outside by more than that, 0 close to an edge (the rasterizer's rounding decides).
inline int Classify(const WindowTriangle& t, double x, double y) {
  const auto distance = [&](glm::dvec2 p, glm::dvec2 q) {
    const glm::dvec2 e = q - p;
    return (e.x * (y - p.y) - e.y * (x - p.x)) / std::sqrt(e.x * e.x + e.y * e.y);
  };
  const double d[3] = {distance(t.a, t.b), distance(t.b, t.c), distance(t.c, t.a)};
  const double margin = 1.0 / 256;
  const bool positive = d[0] > margin && d[1] > margin && d[2] > margin;
  const bool negative = d[0] < -margin && d[1] < -margin && d[2] < -margin;
  if (positive || negative) return 1;  // either winding
  // Outside: beyond some edge on the side away from the triangle's interior.
  const double area = (t.b.x - t.a.x) * (t.c.y - t.a.y) - (t.b.y - t.a.y) * (t.c.x - t.a.x);
  for (double di : d)
    if ((area > 0 ? di : -di) < -margin) return -1;
  return 0;
}

struct PixelCheck {
  std::size_t mismatches = 0;  // pixels whose colour is certain and wrong
  std::size_t triangle_pixels = 0, background_pixels = 0, uncertain = 0;
  std::string first_mismatch;
};

// Compares every pixel with non-overlapping triangles over the background: certain pixels must
// match exactly (alpha 255 too); pixels within a subpixel of an edge are only counted.
inline PixelCheck CheckPixels(const Image& image, Rgb8 background, const std::vector<WindowTriangle>& triangles) {
  PixelCheck check;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      std::optional<Rgb8> expected = background;
      bool inside_one = false;
      for (const WindowTriangle& t : triangles) {
        const int where = Classify(t, x + 0.5, y + 0.5);
        if (where == 1) {
          expected = t.colour;
          inside_one = true;
        } else if (where == 0 && !inside_one) {
          expected.reset();
        }
        if (inside_one) break;
      }
      if (!expected) {
        ++check.uncertain;
        continue;
      }
      ++(inside_one ? check.triangle_pixels : check.background_pixels);
      if (RgbAt(image, x, y) != *expected || image.pixel(x, y)[3] != 255) {
        if (check.mismatches++ == 0) {
          std::ostringstream text;
          text << "pixel (" << x << ", " << y << ") is " << RgbAt(image, x, y) << " alpha " << int{image.pixel(x, y)[3]}
               << ", expected " << *expected;
          check.first_mismatch = text.str();
        }
      }
    }
  }
  return check;
}

// The chapter's "instances" demo (figure 10-3): two cubes in front of the camera, on a
// width x height canvas, through the host's own chain (BuildDrawList), optionally with reversed Z.
inline DrawList ChapterInstances(std::uint32_t width = 600, std::uint32_t height = 600, bool reversed_z = false) {
  Scene scene;
  scene.canvas.width = width;
  scene.canvas.height = height;
  scene.depth.reversed = reversed_z;
  scene.models = {test::ChapterCube()};
  Instance left, right;
  left.transform.translation = glm::dvec3(-1.5, 0, 7);
  right.transform.translation = glm::dvec3(1.25, 2, 7.5);
  scene.instances = {left, right};
  return BuildDrawList(scene);
}

}  // namespace gpu_test
}  // namespace twinraster
