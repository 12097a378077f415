#include "chain/draw_list.hpp"

#include "chain/matrices.hpp"
#include "chain/normals.hpp"

#include <stdexcept>
#include <string>

namespace twinraster {

namespace {

DrawLighting BuildLighting(const Scene& scene, const DrawList& list) {
  DrawLighting lighting;
  lighting.ambient = static_cast<float>(scene.lighting->ambient);
  for (const Light& light : scene.lighting->lights) {
    lighting.lights.push_back(DrawLight{.vector = glm::vec3(light.vector),
                                        .intensity = static_cast<float>(light.intensity),
                                        .point = light.kind == Light::Kind::kPoint});
  }
  lighting.instances.reserve(scene.instances.size());
  for (const Instance& instance : scene.instances) {
    const glm::dmat4 model = ModelMatrix(instance.transform);
    LitInstance lit{.model = glm::mat4x3(glm::dmat4x3(model)), .normal = glm::mat3(0.0f)};
    if (list.meshes[instance.model].shading != Shading::kUnlit) {
      const std::optional<glm::dmat3> normal = NormalMatrix(model);
      // The loader refuses a zero scale on a lit model; a list built from a Scene made in code
      // gets the same refusal here.
      if (!normal) {
        throw std::invalid_argument("an instance of lit model \"" + scene.models[instance.model].name +
                                    "\" has a zero scale, so its normals have no inverse transpose");
      }
      lit.normal = glm::mat3(*normal);
    }
    lighting.instances.push_back(lit);
  }
  return lighting;
}

}  // namespace

DrawList BuildDrawList(const Scene& scene) {
  DrawList list;
  list.width = scene.canvas.width;
  list.height = scene.canvas.height;
  list.background = scene.canvas.background;
  list.reversed_z = scene.depth.reversed;
  list.wireframe = scene.wireframe;

  // Wireframe edges are drawn in the models' own colours: lighting is for filled triangles.
  const bool lit_scene = scene.lighting.has_value() && !scene.wireframe;
  bool any_lit = false;
  for (const Model& model : scene.models) {
    DrawMesh mesh;
    if (lit_scene && model.shading != Shading::kUnlit) {
      mesh.shading = model.shading;
      any_lit = true;
      const std::vector<std::array<glm::dvec3, 3>> normals = CornerNormals(model, model.shading);
      mesh.normals.reserve(normals.size());
      for (const auto& n : normals) mesh.normals.push_back({glm::vec3(n[0]), glm::vec3(n[1]), glm::vec3(n[2])});
    }
    mesh.positions.reserve(model.vertices.size());
    for (const glm::dvec3& v : model.vertices) mesh.positions.emplace_back(v);
    for (const Triangle& t : model.triangles) {
      mesh.triangles.push_back(t.v);
      mesh.colours.push_back(t.colour);
    }
    // Edges keep the triangle colours, as they keep them unlit: vertex colours fill triangles.
    if (!scene.wireframe) mesh.vertex_colours = model.vertex_colours;
    list.meshes.push_back(std::move(mesh));
  }

  const Chain chain = SceneChain(scene);
  list.draws.reserve(scene.instances.size());
  for (const Instance& instance : scene.instances) {
    // The one conversion to float: F is composed in double, then rounded once.
    list.draws.push_back(
        DrawCall{static_cast<std::uint32_t>(instance.model), glm::mat4(InstanceMatrix(chain, instance.transform))});
  }
  if (any_lit) list.lighting = BuildLighting(scene, list);
  return list;
}

void ValidateDrawList(const DrawList& list) {
  if (list.width == 0 || list.height == 0 || list.width > kMaxCanvasSize || list.height > kMaxCanvasSize) {
    throw std::invalid_argument("image size " + std::to_string(list.width) + "x" + std::to_string(list.height) +
                                " is outside 1.." + std::to_string(kMaxCanvasSize));
  }
  for (std::size_t d = 0; d < list.draws.size(); ++d) {
    if (list.draws[d].mesh >= list.meshes.size()) {
      throw std::invalid_argument("draw " + std::to_string(d) + " names mesh " + std::to_string(list.draws[d].mesh) +
                                  " of " + std::to_string(list.meshes.size()));
    }
  }
  if (list.lighting && list.wireframe)
    throw std::invalid_argument("a wireframe list has no lighting: edges are not lit");
  if (list.lighting && list.lighting->instances.size() != list.draws.size()) {
    throw std::invalid_argument("lighting has " + std::to_string(list.lighting->instances.size()) + " instances for " +
                                std::to_string(list.draws.size()) + " draws");
  }
  for (std::size_t m = 0; m < list.meshes.size(); ++m) {
    const DrawMesh& mesh = list.meshes[m];
    if (mesh.colours.size() != mesh.triangles.size()) {
      throw std::invalid_argument("mesh " + std::to_string(m) + " has " + std::to_string(mesh.triangles.size()) +
                                  " triangles but " + std::to_string(mesh.colours.size()) + " colours");
    }
    if (!mesh.vertex_colours.empty() && mesh.vertex_colours.size() != mesh.positions.size()) {
      throw std::invalid_argument("mesh " + std::to_string(m) + " has " + std::to_string(mesh.positions.size()) +
                                  " vertices but " + std::to_string(mesh.vertex_colours.size()) + " vertex colours");
    }
    if (!mesh.vertex_colours.empty() && list.wireframe) {
      throw std::invalid_argument("mesh " + std::to_string(m) +
                                  " has vertex colours in a wireframe list: edges take the triangle colours");
    }
    if (mesh.shading != Shading::kUnlit && mesh.normals.size() != mesh.triangles.size()) {
      throw std::invalid_argument("lit mesh " + std::to_string(m) + " has " + std::to_string(mesh.triangles.size()) +
                                  " triangles but " + std::to_string(mesh.normals.size()) + " corner normals");
    }
    if (mesh.shading != Shading::kUnlit && !list.lighting) {
      throw std::invalid_argument("mesh " + std::to_string(m) + " is lit but the list has no lighting");
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      for (std::uint32_t index : mesh.triangles[t]) {
        if (index >= mesh.positions.size()) {
          throw std::invalid_argument("mesh " + std::to_string(m) + " triangle " + std::to_string(t) + " uses vertex " +
                                      std::to_string(index) + " of " + std::to_string(mesh.positions.size()));
        }
      }
    }
  }
}

}  // namespace twinraster
