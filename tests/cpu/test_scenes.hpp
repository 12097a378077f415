// Scenes for the CPU twin's whole-renderer tests: the chapter's cube and hand-made draw lists.
#pragma once

#include "chain/draw_list.hpp"
#include "chain/matrices.hpp"
#include "scene/scene.hpp"
#include "support/chapter_cube.hpp"

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <numbers>

namespace twinraster::cputest {

// The chapter's scene with cube instances at the given places (camera at the origin).
struct Placed {
  glm::dvec3 translation;
  glm::dvec3 axis{0, 1, 0};
  double degrees = 0;
  double scale = 1;
};
inline DrawList CubeScene(std::uint32_t width, std::uint32_t height, std::initializer_list<Placed> cubes,
                          bool reversed_z = false) {
  Scene scene;
  scene.name = "cubes";
  scene.canvas.width = width;
  scene.canvas.height = height;
  scene.depth.reversed = reversed_z;
  scene.models.push_back(test::ChapterCube());
  for (const Placed& p : cubes) {
    Instance instance;
    instance.model = 0;
    instance.transform.translation = p.translation;
    instance.transform.rotation = Rotation(p.axis, p.degrees);
    instance.transform.scale = glm::dvec3(p.scale);
    scene.instances.push_back(instance);
  }
  return BuildDrawList(scene);
}

// A fan of `n` triangles around `centre`, in clip space (identity matrix, w = 1), ring radius `r`,
// angles jittered so no two edges are alike. Every other triangle is listed clockwise.
inline DrawList Fan(std::uint32_t width, std::uint32_t height, glm::vec2 centre, float r, int n) {
  DrawList list;
  list.width = width;
  list.height = height;
  list.background = {10, 20, 30};
  DrawMesh mesh;
  mesh.positions.push_back({centre.x, centre.y, 0.5f});
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * (i + 0.37 * std::sin(i * 1.7)) / n;
    mesh.positions.push_back(
        {centre.x + r * static_cast<float>(std::cos(a)), centre.y + r * static_cast<float>(std::sin(a)), 0.5f});
  }
  for (int i = 0; i < n; ++i) {
    const auto a = static_cast<std::uint32_t>(1 + i), b = static_cast<std::uint32_t>(1 + (i + 1) % n);
    if (i % 2 == 0) {
      mesh.triangles.push_back({0, a, b});
    } else {
      mesh.triangles.push_back({b, 0, a});  // same triangle, other winding and first vertex
    }
    mesh.colours.push_back({static_cast<std::uint8_t>(20 * i), 100, 200});
  }
  list.meshes.push_back(mesh);
  list.draws.push_back(DrawCall{0, glm::mat4(1.0f)});
  return list;
}

}  // namespace twinraster::cputest
