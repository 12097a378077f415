// A scene file with nothing in view: a quad behind the camera, so no triangle may cover any pixel
// of its 64 x 48 canvas. The verifier alone must call it inconclusive (an empty image is both the
// right answer and what a broken renderer draws); the command-line tests of verify and render
// --verify share it.
#pragma once

namespace twinraster::test {

inline constexpr const char* kNothingInViewScene = R"({
  "canvas": {"width": 64, "height": 48},
  "viewport": {"width": 1, "height": 1, "distance": 1},
  "camera": {"position": [0, 0, 0]},
  "models": {"quad": {"vertices": [[1, 1, 0], [-1, 1, 0], [-1, -1, 0], [1, -1, 0]],
                      "triangles": [[0, 1, 2, "red"], [0, 2, 3, "red"]]}},
  "instances": [{"model": "quad", "transform": {"translation": [0, 0, -7]}}]
})";

}  // namespace twinraster::test
