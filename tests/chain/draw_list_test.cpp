// The draw list both renderers consume: F rounded once from the double chain, and the checks
// every renderer makes before drawing a list built elsewhere.
#include "chain/draw_list.hpp"

#include "chain/matrices.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/chapter_cube.hpp"
#include "support/test_support.hpp"

using namespace twinraster;

TEST_CASE("BuildDrawList: one draw per instance, F rounded to float once from the double chain", "[draw-list]") {
  const Scene scene = LoadScene(test::SourcePath("scenes/cgfs-transforms.json"));
  const DrawList list = BuildDrawList(scene);
  REQUIRE(list.width == 600);
  REQUIRE(list.draws.size() == 2);
  const Chain chain = SceneChain(scene);
  for (std::size_t i = 0; i < list.draws.size(); ++i) {
    const glm::dmat4 exact = InstanceMatrix(chain, scene.instances[i].transform);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) REQUIRE(list.draws[i].F[c][r] == static_cast<float>(exact[c][r]));
  }
  REQUIRE(list.meshes[0].colours.size() == list.meshes[0].triangles.size());
  REQUIRE_NOTHROW(ValidateDrawList(list));
}

TEST_CASE("ValidateDrawList names what a renderer could not draw", "[draw-list]") {
  const DrawList good = BuildDrawList(LoadScene(test::SourcePath("scenes/cgfs-scene.json")));
  const auto message = [](const DrawList& list) {
    try {
      ValidateDrawList(list);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  DrawList list = good;
  list.width = 0;
  REQUIRE(message(list) == "image size 0x600 is outside 1..16384");
  list = good;
  list.height = kMaxCanvasSize + 1;
  REQUIRE(message(list).find("outside 1..16384") != std::string::npos);
  list = good;
  list.draws[0].mesh = 3;
  REQUIRE(message(list) == "draw 0 names mesh 3 of 1");
  list = good;
  list.meshes[0].triangles[5][1] = 8;
  REQUIRE(message(list) == "mesh 0 triangle 5 uses vertex 8 of 8");
  list = good;
  list.meshes[0].colours.pop_back();
  REQUIRE(message(list) == "mesh 0 has 12 triangles but 11 colours");
}

TEST_CASE("ValidateDrawList: lighting must cover every draw and every lit mesh, and never a wireframe",
          "[chain][lighting]") {
  Scene scene;
  scene.canvas = Canvas{.width = 8, .height = 8};
  Model cube = test::ChapterCube();
  cube.shading = Shading::kFlat;
  scene.models.push_back(cube);
  scene.instances.push_back(Instance{});
  scene.lighting = Lighting{.ambient = 0.5, .lights = {}};
  const DrawList lit = BuildDrawList(scene);
  REQUIRE(lit.lighting.has_value());
  REQUIRE_NOTHROW(ValidateDrawList(lit));
  REQUIRE(lit.meshes[0].normals.size() == lit.meshes[0].triangles.size());

  DrawList fewer = lit;
  fewer.lighting->instances.clear();
  CHECK_THROWS_WITH(ValidateDrawList(fewer), HasSubstring("lighting has 0 instances for 1 draws"));
  DrawList no_normals = lit;
  no_normals.meshes[0].normals.pop_back();
  CHECK_THROWS_WITH(ValidateDrawList(no_normals), HasSubstring("corner normals"));
  DrawList no_lighting = lit;
  no_lighting.lighting.reset();
  CHECK_THROWS_WITH(ValidateDrawList(no_lighting), HasSubstring("is lit but the list has no lighting"));
  DrawList wireframe = lit;
  wireframe.wireframe = true;
  CHECK_THROWS_WITH(ValidateDrawList(wireframe), HasSubstring("edges are not lit"));

  // A wireframe scene builds an unlit list: edges in the models' own colours.
  scene.wireframe = true;
  const DrawList edges = BuildDrawList(scene);
  CHECK_FALSE(edges.lighting.has_value());
  CHECK(edges.meshes[0].shading == Shading::kUnlit);
}

TEST_CASE("BuildDrawList carries vertex colours to filled meshes only, and ValidateDrawList checks them",
          "[draw-list][vertex-colours]") {
  Scene scene = LoadScene(test::SourcePath("scenes/vertex-colours.json"));
  REQUIRE(scene.models.at(0).vertex_colours.size() == 8);
  const DrawList filled = BuildDrawList(scene);
  CHECK(filled.meshes[0].vertex_colours == scene.models[0].vertex_colours);
  CHECK(filled.meshes[0].smooth());
  CHECK_FALSE(filled.lighting.has_value());  // unlit: no light buffers for vertex colours alone
  REQUIRE_NOTHROW(ValidateDrawList(filled));
  // A wireframe's edges keep the triangle colours (each its first vertex's, as none is written).
  scene.wireframe = true;
  const DrawList edges = BuildDrawList(scene);
  CHECK(edges.meshes[0].vertex_colours.empty());
  CHECK_FALSE(edges.meshes[0].smooth());
  CHECK(edges.meshes[0].colours[2] == scene.models[0].vertex_colours[4]);  // triangle 2 is [4, 0, 3]

  const auto message = [](const DrawList& list) {
    try {
      ValidateDrawList(list);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  DrawList list = filled;
  list.meshes[0].vertex_colours.pop_back();
  CHECK(message(list) == "mesh 0 has 8 vertices but 7 vertex colours");
  list = filled;
  list.wireframe = true;
  CHECK(message(list) == "mesh 0 has vertex colours in a wireframe list: edges take the triangle colours");
}
