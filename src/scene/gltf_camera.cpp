// A glTF camera node as the chapter's camera, viewport and depth (gltf_build.hpp).
#include "base/trigonometry.hpp"
#include "scene/framing.hpp"
#include "scene/gltf_build.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/scene_error.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace twinraster::gltf {

namespace {

std::string CameraName(const GltfDocument& doc, std::size_t i) {
  return "camera " + std::to_string(i) + (doc.cameras[i].name.empty() ? "" : " \"" + doc.cameras[i].name + "\"");
}

std::string CameraList(const GltfDocument& doc) {
  if (doc.cameras.empty()) return "the file has no cameras";
  std::string list;
  for (std::size_t i = 0; i < doc.cameras.size(); ++i) list += (i ? ", " : "") + CameraName(doc, i);
  return "the file's cameras: " + list;
}

std::size_t CameraIndex(const GltfDocument& doc, const std::string& asked) {
  const bool number = !asked.empty() && asked.size() < 10 && std::all_of(asked.begin(), asked.end(), ::isdigit);
  if (number) {
    const std::size_t index = std::stoul(asked);
    if (index < doc.cameras.size()) return index;
  }
  for (std::size_t i = 0; i < doc.cameras.size(); ++i) {
    if (doc.cameras[i].name == asked) return i;
  }
  throw SceneError(doc.file, "cameras", "--camera " + asked + " names no camera; " + CameraList(doc));
}

// The chapter's camera from the node's world matrix: glTF's camera looks along its -Z with +Y
// up; mirrored in z it looks along +Z, as the chapter's does. Scale is dropped; shear or a
// mirror in the node chain has no camera to stand for it, and is refused.
Camera ChapterCamera(const GltfDocument& doc, const PlacedNode& at) {
  glm::dmat3 r(at.world);
  for (int c = 0; c < 3; ++c) {
    const double length = glm::length(r[c]);
    if (!(length > 1e-12))
      throw SceneError(doc.file, "nodes[" + std::to_string(at.node) + "]",
                       "the camera node's transform scales an axis to 0");
    r[c] /= length;
  }
  const double skew =
      std::max({std::abs(glm::dot(r[0], r[1])), std::abs(glm::dot(r[1], r[2])), std::abs(glm::dot(r[0], r[2]))});
  if (skew > 1e-6 || glm::determinant(r) < 0) {
    throw SceneError(doc.file, "nodes[" + std::to_string(at.node) + "]",
                     "the camera node's transform shears or mirrors: no camera is placed that way");
  }
  const glm::dmat3 mirror(glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, -1));
  return Camera{glm::dvec3(at.world[3]) * kMirror, mirror * r * mirror};
}

// The canvas for a view of `aspect` (width over height): the size asked, else kGltfCanvasSide on
// the longer side.
CanvasSize CanvasFor(double aspect, const std::optional<CanvasSize>& size) {
  if (size) return *size;
  const auto side = [](double x) {
    return static_cast<std::uint32_t>(std::clamp(std::lround(x), 1L, static_cast<long>(kGltfCanvasSide)));
  };
  if (aspect >= 1) return {kGltfCanvasSide, side(kGltfCanvasSide / aspect)};
  return {side(kGltfCanvasSide * aspect), kGltfCanvasSide};
}

}  // namespace

std::optional<PlacedNode> ChooseCamera(const GltfDocument& doc, const std::vector<PlacedNode>& walk,
                                       const std::optional<std::string>& choice) {
  const std::optional<std::size_t> asked = choice ? std::optional(CameraIndex(doc, *choice)) : std::nullopt;
  for (const PlacedNode& placed : walk) {
    const std::optional<std::size_t>& camera = doc.nodes[placed.node].camera;
    if (camera && (!asked || *camera == *asked)) return placed;
  }
  if (asked)
    throw SceneError(doc.file, "cameras", CameraName(doc, *asked) + " is placed by no node of the scene drawn");
  return std::nullopt;
}

void PlaceCamera(const GltfDocument& doc, const PlacedNode& at, const std::optional<CanvasSize>& size, Scene& scene) {
  const GltfCamera& c = doc.cameras[*doc.nodes[at.node].camera];
  scene.camera = ChapterCamera(doc, at);
  Viewport& v = scene.viewport;
  v.distance = 1;
  if (c.orthographic) {
    v.projection = Projection::kOrthographic;
    v.width = 2 * c.xmag;
    v.height = 2 * c.ymag;
  } else {
    v.projection = Projection::kPerspective;
    v.height = 2 * TangentOfRadians(c.yfov / 2);  // the viewport at d = 1 spans yfov
    const double canvas_aspect = size ? static_cast<double>(size->width) / size->height : 1.0;
    v.width = v.height * c.aspect_ratio.value_or(canvas_aspect);
  }
  // The camera's frame is kept whole and unstretched: the viewport grows to the canvas's shape.
  ResizeCanvas(scene, CanvasFor(v.width / v.height, size));
  scene.depth.near = c.znear;
  scene.depth.far = c.zfar.value_or(std::numeric_limits<double>::infinity());
  scene.depth.reversed = false;
  scene.lighting = Headlight(-(scene.camera.rotation[2]));  // toward the camera, against its view
}

}  // namespace twinraster::gltf
