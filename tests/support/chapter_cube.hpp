// The chapter's cube model (vertices ±1, two triangles per face, one colour per face), for tests
// that build scenes in code rather than loading scenes/*.json.
#pragma once

#include "scene/scene.hpp"

namespace twinraster::test {

inline Model ChapterCube() {
  Model cube;
  cube.name = "cube";
  cube.vertices = {glm::dvec3(1, 1, 1),  glm::dvec3(-1, 1, 1),  glm::dvec3(-1, -1, 1),  glm::dvec3(1, -1, 1),
                   glm::dvec3(1, 1, -1), glm::dvec3(-1, 1, -1), glm::dvec3(-1, -1, -1), glm::dvec3(1, -1, -1)};
  const Rgb8 red{255, 0, 0}, green{0, 255, 0}, blue{0, 0, 255}, yellow{255, 255, 0}, purple{255, 0, 255},
      cyan{0, 255, 255};
  cube.triangles = {{{0, 1, 2}, red},    {{0, 2, 3}, red},    {{4, 0, 3}, green},  {{4, 3, 7}, green},
                    {{5, 4, 7}, blue},   {{5, 7, 6}, blue},   {{1, 5, 6}, yellow}, {{1, 6, 2}, yellow},
                    {{4, 5, 1}, purple}, {{4, 1, 0}, purple}, {{2, 6, 7}, cyan},   {{2, 7, 3}, cyan}};
  return cube;
}

}  // namespace twinraster::test
