#include "book/book_renderer.hpp"

#include "book/book_chain.hpp"
#include "book/book_lines.hpp"
#include "book/book_projection.hpp"

#include <cmath>
#include <sstream>
#include <vector>

namespace twinraster::book {

namespace {

bool WithinReach(CanvasPoint p) {
  return std::abs(p.x) <= kFarthestEndpoint && std::abs(p.y) <= kFarthestEndpoint;  // false for NaN
}

// Where an instance is in the scene file: grids' copies are written out in Scene::instances, so
// the file's index is found by undoing that.
std::string Path(const Scene& scene, std::size_t instance) {
  std::size_t extra = 0;  // copies beyond the first of the grids before `instance`
  for (const InstanceGrid& grid : scene.grids) {
    if (instance < grid.first) break;
    if (instance < grid.first + grid.copies()) {
      return "instances[" + std::to_string(grid.written) + "] (grid copy " + std::to_string(instance - grid.first) +
             ")";
    }
    extra += grid.copies() - 1;
  }
  return "instances[" + std::to_string(instance - extra) + "]";
}

// The chapter's RenderModel: project every vertex once, then draw each triangle.
void RenderModel(DemoCanvas& canvas, const Scene& scene, std::size_t instance, const Mat4x4& transform) {
  const Model& model = scene.models[scene.instances[instance].model];
  std::vector<Vertex4> camera_space;
  std::vector<CanvasPoint> projected;
  camera_space.reserve(model.vertices.size());
  projected.reserve(model.vertices.size());
  for (const glm::dvec3& v : model.vertices) {
    camera_space.push_back(MultiplyMV(transform, {v.x, v.y, v.z, 1}));
    projected.push_back(ProjectVertex(camera_space.back(), scene.viewport, scene.canvas));
  }
  for (std::size_t t = 0; t < model.triangles.size(); ++t) {
    const Triangle& triangle = model.triangles[t];
    for (std::uint32_t v : triangle.v) {
      if (WithinReach(projected[v])) continue;
      // Only a drawn vertex matters: the demo projects unused ones too, and never looks at them.
      std::ostringstream problem;
      problem.precision(17);
      problem << "model \"" << model.name << "\" triangle " << t << ": vertex " << v
              << " is at camera-space z = " << camera_space[v][2] << " and projects to ";
      if (std::isfinite(projected[v].x) && std::isfinite(projected[v].y)) {
        problem << "canvas (" << projected[v].x << ", " << projected[v].y << ")";
      } else {
        problem << "no canvas point";
      }
      problem << "; the demos walk every step of a line, on the canvas or off it, so the book's rules stop at 2^20 "
                 "pixels from the centre (the Vulkan rules clip instead)";
      throw BookRulesError(Path(scene, instance), problem.str());
    }
    DrawWireframeTriangle(canvas, projected[triangle.v[0]], projected[triangle.v[1]], projected[triangle.v[2]],
                          triangle.colour);
  }
}

}  // namespace

void CheckBookRules(const Scene& scene) {
  if (scene.viewport.projection == Projection::kOrthographic) {
    throw BookRulesError("viewport.projection",
                         "the book's demos only project in perspective (x·d/z, y·d/z); "
                         "this scene is orthographic");
  }
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    if (scene.instances[i].transform.steps) {
      throw BookRulesError(Path(scene, i) + ".transform",
                           "a transform written as a list of steps; the book's demos always scale, then rotate, "
                           "then translate (write the transform as an object)");
    }
  }
  const Canvas& c = scene.canvas;
  if (c.width % 2 != 0 || c.height % 2 != 0) {
    throw BookRulesError("canvas", "the book's rules need an even width and height (this canvas is " +
                                       std::to_string(c.width) + " x " + std::to_string(c.height) +
                                       "): the demos put the origin at (Cw/2, Ch/2), which must be a whole pixel");
  }
}

Image RenderScene(const Scene& scene) {
  CheckBookRules(scene);
  DemoCanvas canvas(scene.canvas.width, scene.canvas.height, scene.canvas.background);
  const Mat4x4 camera = MakeCameraMatrix(scene.camera);
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    RenderModel(canvas, scene, i, MultiplyMM4(camera, MakeInstanceTransform(scene.instances[i].transform)));
  }
  return canvas.TakeImage();
}

}  // namespace twinraster::book
