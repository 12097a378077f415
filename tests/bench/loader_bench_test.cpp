// bench --loaders on a tiny .glb built here: the JSON scene it writes loads as the same Scene, its
// M_Model decompositions rebuild the matrices, and the command's --json has the shape
// docs/schemas/bench-loaders.schema.json describes with positive, consistent numbers (no timing
// is asserted: the machine is shared).
#include "bench/loader_bench.hpp"

#include "bench/scene_json_writer.hpp"
#include "chain/matrices.hpp"
#include "scene/obj_scene.hpp"
#include "scene/rotation.hpp"
#include "support/catch.hpp"
#include "support/gltf_bytes.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

using namespace twinraster;
using Json = nlohmann::json;

#if defined(__SANITIZE_ADDRESS__)
#define TWINRASTER_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TWINRASTER_UNDER_ASAN 1
#endif
#endif
#ifdef TWINRASTER_UNDER_ASAN
constexpr bool kMallinfoCounts = false;
#else
constexpr bool kMallinfoCounts = true;
#endif

namespace {

using test::AppendBytes;

// A .glb of one mesh, a unit square (two triangles), placed by two nodes: a child under a root
// with translation, rotation and a non-uniform scale, and a node with its own matrix.
std::vector<std::uint8_t> TinyGlb() {
  std::vector<std::uint8_t> bin;
  for (const float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.f, 0.f}) AppendBytes(bin, f);
  for (const int i : {0, 1, 2, 0, 2, 3}) AppendBytes(bin, static_cast<std::uint16_t>(i));
  const double half = std::sqrt(0.5);
  const Json doc = {
      {"asset", {{"version", "2.0"}}},
      {"buffers", {{{"byteLength", bin.size()}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
      {"materials", {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.5, 0.9, 1}}}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 0}}}}}}},
      {"nodes",
       {{{"children", {1}}, {"translation", {1, 2, 3}}, {"rotation", {0, half, 0, half}}, {"scale", {2, 1, 0.5}}},
        {{"mesh", 0}, {"translation", {0, 0, -1}}},
        {{"mesh", 0}, {"matrix", {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 4, 0, 0, 1}}}}},
      {"scenes", {{{"nodes", {0, 2}}}}},
  };
  return test::Glb(doc.dump(), bin);
}

std::filesystem::path WriteTinyGlb(const test::TempDir& dir) {
  const std::vector<std::uint8_t> bytes = TinyGlb();
  const std::filesystem::path file = dir / "tiny.glb";
  test::WriteFile(file, std::string(bytes.begin(), bytes.end()));
  return file;
}

}  // namespace

TEST_CASE("DecomposeModelMatrix rebuilds rotations, mirrors and half turns through the JSON's axis and angle",
          "[bench][loaders]") {
  const glm::dmat4 mirror = Scale({1, 1, -1});
  const std::vector<glm::dmat4> matrices = {
      glm::dmat4(1.0),
      mirror,
      Translation({1, -2, 3}) * Rotation4(Rotation(glm::normalize(glm::dvec3(1, 2, 3)), 37)) * Scale({2, 0.5, 3}),
      mirror * Rotation4(Rotation({0, 1, 0}, 180)) * Scale({4, 4, 4}),
      Rotation4(Rotation(glm::normalize(glm::dvec3(1, 1, 0)), 179.9999999)),
      mirror * Translation({5, 0, 0}) * Rotation4(Rotation({1, 0, 0}, -90)),
  };
  for (std::size_t i = 0; i < matrices.size(); ++i) {
    INFO(i);
    const bench::ObjectTransform t = bench::DecomposeModelMatrix(matrices[i]);
    REQUIRE(t.residual < 1e-12);
  }
  // A shear has no object form: the residual says how far off it is.
  glm::dmat4 shear(1.0);
  shear[1][0] = 0.5;
  REQUIRE(bench::DecomposeModelMatrix(shear).residual > 0.1);
}

TEST_CASE("SceneAsJson writes a glTF file's Scene as JSON that loads as the same Scene", "[bench][loaders]") {
  const test::TempDir dir;
  const Scene gltf = LoadSceneOrObj(WriteTinyGlb(dir));
  REQUIRE(gltf.instances.size() == 2);
  for (const bench::JsonDigits digits : {bench::JsonDigits::kExact, bench::JsonDigits::kFloat}) {
    const std::filesystem::path file = dir / "scene.json";
    test::WriteFile(file, bench::SceneAsJson(gltf, digits));
    const Scene json = LoadSceneOrObj(file);
    REQUIRE(json.models.size() == gltf.models.size());
    REQUIRE(json.models[0].vertices == gltf.models[0].vertices);  // float-valued: both spellings exact
    REQUIRE(json.models[0].triangles.size() == 2);
    REQUIRE(json.models[0].triangles[1].colour == gltf.models[0].triangles[1].colour);
    REQUIRE(json.models[0].shading == gltf.models[0].shading);
    REQUIRE(json.instances.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
      const glm::dmat4 a = ModelMatrix(gltf.instances[i].transform), b = ModelMatrix(json.instances[i].transform);
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) REQUIRE(std::abs(a[c][r] - b[c][r]) < 1e-12);
    }
    REQUIRE(glm::length(json.camera.position - gltf.camera.position) < 1e-12);
    REQUIRE(json.lighting.has_value() == gltf.lighting.has_value());
  }
}

TEST_CASE("bench --loaders --json on a tiny .glb: every row, positive and consistent numbers",
          "[bench][loaders][cli]") {
  const test::TempDir dir;
  const std::filesystem::path glb = WriteTinyGlb(dir);
  const test::CliResult r = test::RunCli(
      {"bench", "--loaders", "--gltf", glb.string(), "--runs", "2", "--json", "-q", "--out", (dir / "out").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const Json j = Json::parse(r.out);
  REQUIRE(j["format"] == "twinraster.bench-loaders/1");
  REQUIRE(j["runs"] == 2);
  REQUIRE(j["memory_runs"] == 2);
  REQUIRE(j["models"] == 1);
  REQUIRE(j["instances"] == 2);
  REQUIRE(j["triangles"] == 2);
  REQUIRE(j["drawn_triangles"] == 4);
  REQUIRE(j["rows"].size() == 3);
  const std::vector<std::string> loaders = {"glb", "json-exact", "json-float"};
  for (std::size_t i = 0; i < 3; ++i) {
    const Json& row = j["rows"][i];
    INFO(row.dump());
    REQUIRE(row["loader"] == loaders[i]);
    REQUIRE(row["bytes"].get<double>() > 0);
    REQUIRE(row["load_ms"].get<double>() > 0);
    REQUIRE(row["load_ns_per_triangle"].get<double>() == Approx(row["load_ms"].get<double>() * 1e6 / 2));
    REQUIRE(row["load_ns_per_byte"].get<double>() ==
            Approx(row["load_ms"].get<double>() * 1e6 / row["bytes"].get<double>()));
    // AddressSanitizer's allocator does not report to mallinfo2, so the heap reads 0 there.
    REQUIRE((kMallinfoCounts ? row["scene_heap_bytes"].get<double>() > 0 : row["scene_heap_bytes"].get<double>() == 0));
    REQUIRE(row["scene_heap_bytes_per_triangle"].get<double>() == Approx(row["scene_heap_bytes"].get<double>() / 2));
    REQUIRE(row["peak_rss_bytes"].get<double>() >= 0);
    REQUIRE(row["same_counts"] == true);
    REQUIRE(row["max_vertex_difference"] == 0.0);
    REQUIRE(row["max_model_matrix_difference"].get<double>() < 1e-12);
    REQUIRE(row["processes"]["render_ms"].get<double>() > 0);
    // Null only without /usr/bin/time (Debian's package time).
    const Json& peak = row["processes"]["explain_max_rss_kib"];
    REQUIRE((peak.is_null() ? !std::filesystem::exists("/usr/bin/time") : peak.get<double>() > 0));
  }
  REQUIRE(j["rows"][0]["load_ratio"] == 1.0);
  REQUIRE(j["rows"][1]["load_ratio"].get<double>() ==
          Approx(j["rows"][1]["load_ms"].get<double>() / j["rows"][0]["load_ms"].get<double>()));
  // The JSON spelling every double exactly is never shorter than the one of float digits.
  REQUIRE(j["rows"][1]["bytes"].get<double>() >= j["rows"][2]["bytes"].get<double>());
  REQUIRE(j["process_floor"]["help_ms"].get<double>() > 0);
  REQUIRE(Json::parse(test::ReadFile(dir / "out" / "loaders.json"))["rows"].size() == 3);
  REQUIRE(test::ReadFile(dir / "out" / "loaders.txt").find("json-float") != std::string::npos);
}

TEST_CASE("bench --loaders names a missing asset, and runs alone", "[bench][loaders][cli]") {
  const test::CliResult missing = test::RunCli({"bench", "--loaders", "--gltf", "/nonexistent/x.glb", "-q"});
  REQUIRE(missing.exit_code == 2);
  REQUIRE(missing.err.find("/nonexistent/x.glb") != std::string::npos);
  const test::CliResult both = test::RunCli({"bench", "--loaders", "--verify", "-q"});
  REQUIRE(both.exit_code == 2);
  REQUIRE(both.err.find("one at a time") != std::string::npos);
}
