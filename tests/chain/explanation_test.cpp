// chain/explanation.hpp on its own: the typed Explanation holds the chain's matrices, the
// instances asked for, and the vertices ExplainOptions chose, with the one to follow marked.
#include "chain/explanation.hpp"

#include "base/usage_error.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

using namespace twinraster;

namespace {

Scene Shipped(const std::string& name) { return LoadScene(test::SourcePath("scenes/" + name)); }

}  // namespace

TEST_CASE("Explain: the chain's matrices, one traced vertex per instance by default, the first inside the clip volume",
          "[chain][explain]") {
  const Scene scene = Shipped("cgfs-transforms.json");
  const Explanation e = Explain(scene, {});
  REQUIRE(e.scene == &scene);
  CHECK(e.chain.projection == ProjectionMatrix(scene.viewport, scene.canvas, scene.depth));
  CHECK(e.chain.camera == CameraMatrix(scene.camera));
  CHECK(e.canvas_to_clip * e.viewport_to_canvas * e.p == e.chain.projection);
  REQUIRE(e.instances.size() == scene.instances.size());
  for (std::size_t i = 0; i < e.instances.size(); ++i) {
    const InstanceExplanation& x = e.instances[i];
    INFO("instance " << i);
    CHECK(x.index == i);
    CHECK(x.model == &scene.models[scene.instances[i].model]);
    CHECK(x.model_matrix == ModelMatrix(scene.instances[i].transform));
    CHECK(x.f == InstanceMatrix(e.chain, scene.instances[i].transform));
    REQUIRE(x.vertices.size() == 1);
    CHECK(x.traced == 0);
    const std::size_t v = x.vertices[0].index;
    CHECK(x.vertices[0].trace.inside);
    for (std::size_t earlier = 0; earlier < v; ++earlier) {
      CHECK_FALSE(TraceVertex(scene, e.chain, x.model_matrix, x.model->vertices[earlier]).inside);
    }
  }
}

TEST_CASE("Explain: every vertex with ExplainVertices::kAll, the traced one marked, and --vertex picks it",
          "[chain][explain]") {
  const Scene scene = Shipped("cgfs-transforms.json");
  const Explanation one = Explain(scene, {});
  const Explanation all = Explain(scene, {{}, {}, ExplainVertices::kAll});
  for (std::size_t i = 0; i < all.instances.size(); ++i) {
    const InstanceExplanation& x = all.instances[i];
    REQUIRE(x.vertices.size() == x.model->vertices.size());
    for (std::size_t v = 0; v < x.vertices.size(); ++v) CHECK(x.vertices[v].index == v);
    CHECK(x.vertices[x.traced].index == one.instances[i].vertices[0].index);
  }
  const Explanation picked = Explain(scene, {1, 6, ExplainVertices::kAll});
  REQUIRE(picked.instances.size() == 1);
  CHECK(picked.instances[0].index == 1);
  CHECK(picked.instances[0].traced == 6);
  const Explanation only = Explain(scene, {1, 6, ExplainVertices::kTraced});
  REQUIRE(only.instances[0].vertices.size() == 1);
  CHECK(only.instances[0].vertices[0].index == 6);
  CHECK(only.instances[0].vertices[0].trace.object == glm::dvec3(-1, -1, -1));
  CHECK_THROWS_AS(Explain(scene, {2, {}, ExplainVertices::kTraced}), UsageError);
  CHECK_THROWS_AS(Explain(scene, {{}, 8, ExplainVertices::kTraced}), UsageError);
}

TEST_CASE("Explain: a lit instance has its normal matrix and each traced vertex's light, and grids and lists are typed",
          "[chain][explain]") {
  const Scene lit = Shipped("normals-stretched-square.json");
  const Explanation e = Explain(lit, {{}, {}, ExplainVertices::kAll});
  REQUIRE(e.lighting_used);
  for (const InstanceExplanation& x : e.instances) {
    REQUIRE(x.lit);
    REQUIRE(x.normal_matrix);
    for (const TracedVertex& v : x.vertices) REQUIRE(v.light);
  }
  const Scene grid = Shipped("catlike-grid.json");
  const Explanation g = Explain(grid, {});
  REQUIRE(g.instances.size() == kExplainedInstances);
  REQUIRE(g.instances[1].grid_copy);
  CHECK(g.instances[1].grid_copy->grid == &grid.grids[0]);
  CHECK(g.instances[1].grid_copy->ijk == std::array<std::size_t, 3>{1, 0, 0});
  const Scene steps = Shipped("cgfs-figure-10-5.json");
  const Explanation list = Explain(steps, {1, {}, ExplainVertices::kTraced});
  const InstanceExplanation& listed = list.instances[0];
  REQUIRE(listed.steps);
  REQUIRE(listed.steps->size() == 2);
  CHECK((*listed.steps)[0].kind == TransformStep::Kind::kTranslation);
  const glm::dmat4 product = (*listed.steps)[1].matrix * (*listed.steps)[0].matrix;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) CHECK(product[c][r] == Approx(listed.model_matrix[c][r]).margin(1e-12));
  }
}
