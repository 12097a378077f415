#include "draw_list.hpp"

#include "matrices.hpp"

namespace twinraster {

DrawList BuildDrawList(const Scene& scene) {
  DrawList list;
  list.width = scene.canvas.width;
  list.height = scene.canvas.height;
  list.background = scene.canvas.background;
  list.reversed_z = scene.depth.reversed;

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

}  // namespace twinraster
