#include "chain/draw_list.hpp"

#include "chain/matrices.hpp"

#include <stdexcept>
#include <string>

namespace twinraster {

DrawList BuildDrawList(const Scene& scene) {
  DrawList list;
  list.width = scene.canvas.width;
  list.height = scene.canvas.height;
  list.background = scene.canvas.background;
  list.reversed_z = scene.depth.reversed;
  list.wireframe = scene.wireframe;

  for (const Model& model : scene.models) {
    DrawMesh mesh;
    mesh.positions.reserve(model.vertices.size());
    for (const glm::dvec3& v : model.vertices) mesh.positions.emplace_back(v);
    for (const Triangle& t : model.triangles) {
      mesh.triangles.push_back(t.v);
      mesh.colours.push_back(t.colour);
    }
    list.meshes.push_back(std::move(mesh));
  }

  const Chain chain = SceneChain(scene);
  for (const Instance& instance : scene.instances) {
    // The one conversion to float: F is composed in double, then rounded once.
    list.draws.push_back(DrawCall{static_cast<std::uint32_t>(instance.model),
                                  glm::mat4(InstanceMatrix(chain, instance.transform))});
  }
  return list;
}

void ValidateDrawList(const DrawList& list) {
  if (list.width == 0 || list.height == 0 || list.width > kMaxCanvasSize ||
      list.height > kMaxCanvasSize) {
    throw std::invalid_argument("image size " + std::to_string(list.width) + "x" +
                                std::to_string(list.height) + " is outside 1.." +
                                std::to_string(kMaxCanvasSize));
  }
  for (std::size_t d = 0; d < list.draws.size(); ++d) {
    if (list.draws[d].mesh >= list.meshes.size()) {
      throw std::invalid_argument("draw " + std::to_string(d) + " names mesh " +
                                  std::to_string(list.draws[d].mesh) + " of " +
                                  std::to_string(list.meshes.size()));
    }
  }
  for (std::size_t m = 0; m < list.meshes.size(); ++m) {
    const DrawMesh& mesh = list.meshes[m];
    if (mesh.colours.size() != mesh.triangles.size()) {
      throw std::invalid_argument("mesh " + std::to_string(m) + " has " +
                                  std::to_string(mesh.triangles.size()) + " triangles but " +
                                  std::to_string(mesh.colours.size()) + " colours");
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      for (std::uint32_t index : mesh.triangles[t]) {
        if (index >= mesh.positions.size()) {
          throw std::invalid_argument("mesh " + std::to_string(m) + " triangle " +
                                      std::to_string(t) + " uses vertex " + std::to_string(index) +
                                      " of " + std::to_string(mesh.positions.size()));
        }
      }
    }
  }
}

}  // namespace twinraster
