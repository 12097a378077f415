// What every band of a frame needs and the first band to ask computes once for all: the exact
// light, each lit draw's corner colours and each mesh's neighbours (mesh_neighbours.hpp). Bands
// asking for something another band is computing wait for it. It does not walk primitives or pixels.
#pragma once

#include "scene/scene.hpp"
#include "truth/truth_renderer.hpp"
#include "verify/mesh_neighbours.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace twinraster::verify {

class FrameShared {
 public:
  using Corners = std::vector<std::array<glm::dvec3, 3>>;  // per triangle, its corners' colours

  // Lighting only for a filled frame with lighting or vertex colours (a wireframe's lines are unlit).
  FrameShared(const Scene& scene, const DrawList& list);

  bool lit() const { return light_.has_value(); }
  // Draw d's lit corner colours: kept for the other bands while the frame's fit a budget, else
  // computed into `scratch` each time.
  const Corners& CornerColours(std::size_t d, Corners& scratch) const;
  const std::vector<std::array<Neighbour, 3>>& Neighbours(std::size_t mesh) const;

 private:
  template <class T>
  struct Once {
    std::once_flag flag;
    T value;
  };

  const DrawList& list_;
  std::optional<truth::ExactLight> light_;
  std::unique_ptr<Once<Corners>[]> corners_;                                   // per draw; null: over the budget
  std::unique_ptr<Once<std::vector<std::array<Neighbour, 3>>>[]> neighbours_;  // per mesh
};

}  // namespace twinraster::verify
