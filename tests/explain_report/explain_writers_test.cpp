// explain's writers on a typed Explanation: the text traces what the explanation holds and shows
// no "-0"; the JSON keeps every double as computed; the chain page draws the explanation's own
// numbers (change one there and the page changes), with no model looked up by name.
#include "chain/explanation.hpp"
#include "explain_report/chain_page.hpp"
#include "explain_report/explain_json.hpp"
#include "explain_report/explain_text.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/negative_zero.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <string>

using namespace twinraster;

namespace {

Scene Shipped(const std::string& name) { return LoadScene(test::SourcePath("scenes/" + name)); }

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A matrix cell set to a negative zero, as C_T⁻¹ of a camera at the origin has.
Explanation WithNegativeZeros(const Scene& scene, ExplainVertices vertices) {
  Explanation e = Explain(scene, {{}, {}, vertices});
  e.chain.camera[3][0] = -0.0;
  e.camera_translation_inverse[3][1] = -0.0;
  e.instances[0].model_matrix[3][2] = -0.0;
  e.instances[0].vertices[e.instances[0].traced].trace.world.x = -0.0;
  return e;
}

}  // namespace

TEST_CASE("ExplainText writes the vertices the explanation traced, and notes which one by default",
          "[report][explain]") {
  const Scene scene = Shipped("cgfs-transforms.json");
  const std::string one = explain_report::ExplainText(Explain(scene, {}));
  CHECK(Count(one, "\n  vertex ") == scene.instances.size());
  CHECK(Count(one, "\n  traced: vertex ") == scene.instances.size());
  CHECK_THAT(one, HasSubstring(" the clip volume (--vertex V for another, --all-vertices for all)"));
  const std::string all = explain_report::ExplainText(Explain(scene, {{}, {}, ExplainVertices::kAll}));
  CHECK(Count(all, "\n  vertex ") == 16);  // two cubes of 8 vertices
  CHECK(Count(all, "traced: vertex") == 0);
  const std::string picked = explain_report::ExplainText(Explain(scene, {1, 6, ExplainVertices::kTraced}));
  CHECK(Count(picked, "\n  vertex 6\n") == 1);
  CHECK(Count(picked, "traced: vertex") == 0);
}

TEST_CASE("ExplainText and the chain page never show -0, and ExplainJson keeps it", "[report][explain]") {
  const Scene scene = Shipped("cgfs-transforms.json");
  const std::string text = explain_report::ExplainText(WithNegativeZeros(scene, ExplainVertices::kTraced));
  CHECK_FALSE(test::HasNegativeZero(text));
  const std::string page = explain_report::ChainPageHtml(WithNegativeZeros(scene, ExplainVertices::kAll));
  CHECK_FALSE(test::HasNegativeZero(page));
  const std::string json = explain_report::ExplainJson(WithNegativeZeros(scene, ExplainVertices::kAll)).dump(2);
  CHECK(json.find("-0.0") != std::string::npos);
  // The check itself: a lone -0 is caught, other numbers with "-0" in them are not.
  CHECK(test::HasNegativeZero("(-0, 1)"));
  CHECK(test::HasNegativeZero("[ -0 ]"));
  CHECK_FALSE(test::HasNegativeZero("-0.5 1e-05 -0.0"));
}

TEST_CASE("ExplainJson: format twinraster.explain/3, an entry per explained instance and traced vertex",
          "[report][explain]") {
  const Scene scene = Shipped("cgfs-transforms.json");
  const nlohmann::ordered_json j = explain_report::ExplainJson(Explain(scene, {1, 6, ExplainVertices::kTraced}));
  CHECK(j.at("format") == explain_report::kExplainJsonFormat);
  CHECK(std::string(explain_report::kExplainJsonFormat) == "twinraster.explain/3");
  REQUIRE(j.at("instances").size() == 1);
  CHECK(j.at("instances")[0].at("index") == 1);
  REQUIRE(j.at("instances")[0].at("vertices").size() == 1);
  CHECK(j.at("instances")[0].at("vertices")[0].at("index") == 6);
}

TEST_CASE("The chain page draws the typed explanation: its traced vertex, its matrices, its model",
          "[report][explain]") {
  const Scene scene = Shipped("cgfs-transforms.json");
  Explanation e = Explain(scene, {{}, {}, ExplainVertices::kAll});
  const std::string page = explain_report::ChainPageHtml(e);
  CHECK(Count(page, "<figure class=\"chain-panel\"") == 6);
  const InstanceExplanation& x = e.instances[0];
  CHECK_THAT(page, HasSubstring("takes vertex " + std::to_string(x.vertices[x.traced].index) +
                                " of instance 0 (model &quot;" + x.model->name + "&quot;)"));
  // The page shows what the explanation holds, not numbers of its own.
  e.instances[0].traced = 5;
  e.chain.camera[3][0] = 1234.5;
  e.instances[0].vertices[5].trace.framebuffer = {17.25, 33.5, 0.5};
  const std::string changed = explain_report::ChainPageHtml(e);
  CHECK_THAT(changed, HasSubstring("takes vertex 5 of instance 0"));
  CHECK_THAT(changed, HasSubstring("1234.5"));
  CHECK_THAT(changed, HasSubstring("pixel (17, 33), depth 0.5"));

  const Scene lit = Shipped("lit-flat.json");
  const std::string lit_page = explain_report::ChainPageHtml(Explain(lit, {{}, {}, ExplainVertices::kAll}));
  CHECK(Count(lit_page, "<figure class=\"chain-panel\"") == 7);
}
