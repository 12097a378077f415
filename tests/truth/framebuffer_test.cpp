// ExactFramebuffer and ExactClipSpace against hand-computed values.
#include "chain/draw_list.hpp"
#include "chain/matrices.hpp"
#include "support/catch.hpp"
#include "truth/truth_renderer.hpp"

using namespace twinraster;

TEST_CASE("ExactFramebuffer: the viewport transform in double", "[truth][viewport]") {
  CHECK(truth::ExactFramebuffer({0, 0, 0.5, 1}, 8, 4) == glm::dvec3(4, 2, 0.5));
  CHECK(truth::ExactFramebuffer({-1, -1, 0, 1}, 8, 4) == glm::dvec3(0, 0, 0));   // top left, near
  CHECK(truth::ExactFramebuffer({2, 2, 2, 2}, 8, 4) == glm::dvec3(8, 4, 1));     // bottom right, far
  CHECK(truth::ExactFramebuffer({1, -2, 1, 2}, 8, 4) == glm::dvec3(6, 0, 0.5));  // divided by w
  // No snapping: a position a millionth of a pixel off stays there.
  const glm::dvec3 p = truth::ExactFramebuffer({0.25 + 1e-6 / 300, 0, 0.3, 1}, 600, 600);
  CHECK(p.x == Approx(375.000001).epsilon(0).margin(1e-9));
  CHECK(p.z == 0.3);
}

TEST_CASE("ExactClipSpace: the chapter's chain in double, one vector per instance", "[truth][viewport]") {
  // Camera at the origin, viewport 1 x 1 at d = 1, canvas 600 x 600, depth 0.1 .. 100. The vertex
  // (1, 1, 1) of an instance at (0, 0, 5) is at (1, 1, 6) in camera space: clip x = 1 · 600 · 2/600
  // = 2, y = -2 (Vulkan's y is down), w = 6, z = A · 6 + B with A = 100/99.9, B = -10/99.9.
  Scene scene;
  scene.canvas = {600, 600, {255, 255, 255}};
  Model model;
  model.vertices = {{1, 1, 1}, {0, 0, 0}};
  model.triangles = {{{0, 1, 1}, {}}};
  scene.models.push_back(model);
  Instance instance;
  instance.transform.translation = {0, 0, 5};
  scene.instances = {instance, instance};

  const truth::ExactClipPositions clip = truth::ExactClipSpace(scene);
  REQUIRE(clip.size() == 2);
  REQUIRE(clip[0].size() == 2);
  const glm::dvec4 v = clip[0][0];
  CHECK(v.x == Approx(2).epsilon(1e-15));
  CHECK(v.y == Approx(-2).epsilon(1e-15));
  CHECK(v.z == Approx((100.0 * 6 - 10) / 99.9).epsilon(1e-15));
  CHECK(v.w == Approx(6).epsilon(1e-15));
  const glm::dvec3 fb = truth::ExactFramebuffer(v, 600, 600);
  CHECK(fb.x == Approx(400).epsilon(1e-15));
  CHECK(fb.y == Approx(200).epsilon(1e-15));
  CHECK(fb.z == Approx((100 - 10.0 / 6) / 99.9).epsilon(1e-15));

  // The same as the host's double F, and close to the float F the renderers get.
  const glm::dmat4 f = InstanceMatrix(SceneChain(scene), instance.transform);
  CHECK(clip[1][0] == f * glm::dvec4(1, 1, 1, 1));
  const DrawList list = BuildDrawList(scene);
  const glm::vec4 float_clip = list.draws[0].F * glm::vec4(1, 1, 1, 1);
  for (int k = 0; k < 4; ++k) CHECK(double(float_clip[k]) == Approx(v[k]).epsilon(1e-6));
}
