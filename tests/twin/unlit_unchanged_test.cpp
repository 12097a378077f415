// Scenes without lighting are untouched by it: the twin's image of every unlit shipped scene has
// the same bytes as before lighting existed. The hashes were recorded from the build of commit
// 43c77f2, the last one without lighting (FNV-1a, 64 bits, over the RGBA bytes); lavapipe's images
// equal the twin's, which the other twin tests hold.
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/image_hashes.hpp"

#include <map>
#include <string>

using namespace twinraster;

TEST_CASE("Unlit scenes render byte for byte as they did before lighting existed", "[twin][lighting]") {
  const std::map<std::string, std::uint64_t> before = {
      {"bench/spheres-100k", 0x37a78d2d16c4a99eull},
      {"catlike-grid", 0xe7f868f2e6f4503eull},
      {"catlike-orthographic", 0xdfd10cd27b1501cdull},
      {"catlike-rotations", 0x382c0eb8cf8d793dull},
      {"cgfs-figure-10-4", 0x9b99161ba8782c08ull},
      {"cgfs-figure-10-5", 0xdc68e08f759c596aull},
      {"cgfs-instances", 0xa03969e938d4f8a4ull},
      {"cgfs-scene", 0xfa1279a750a1e2a5ull},
      {"cgfs-transforms", 0x8b49ba82f867a720ull},
      {"hard/accumulated-rotation", 0xb45dfb89067937d8ull},
      {"hard/accumulated-rotation-reorthonormalized", 0xb45dfb89067937d8ull},
      {"hard/camera-inside-cube", 0x5815b0751c6a4efcull},
      {"hard/degenerate", 0xec29f73bd4b14325ull},
      {"hard/depth-ratio-1e-1", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-1-reversed", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-2", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-2-reversed", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-3", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-3-reversed", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-4", 0xae4bba34988bb181ull},
      {"hard/depth-ratio-1e-4-reversed", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-5", 0x6d0a9461d77bc7e9ull},
      {"hard/depth-ratio-1e-5-reversed", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-6", 0x1a4c299f37804941ull},
      {"hard/depth-ratio-1e-6-reversed", 0x72e2b4984dce7de1ull},
      {"hard/extreme-scales", 0x5fb2a1cfd6606e2full},
      {"hard/far-1e3", 0x3f211a43b2e35737ull},
      {"hard/far-1e5", 0x3f211a43b2e35737ull},
      {"hard/far-1e7", 0x3f211a43b2e35737ull},
      {"hard/near-plane", 0xc9d1eb1617a6a4e9ull},
      {"hard/orthographic-edge-on", 0xa31452dda2d79823ull},
      {"hard/orthographic-near-far", 0xea923dcec436427bull},
      {"hard/orthographic-near-far-reversed", 0xea923dcec436427bull},
      {"hard/up-near-parallel", 0xda33710c96bb7bf9ull},
      {"hard/zero-negative-scale", 0xfaac7a5f12e15661ull},
      {"lookat", 0x228471f6469ca600ull},
  };
  const std::size_t checked = test::ForEachRecordedScene(
      before, [](const std::filesystem::path& file, const std::string& name, std::uint64_t hash) {
        INFO(name);
        const Scene scene = LoadScene(file);
        REQUIRE_FALSE(scene.lighting.has_value());
        CHECK(test::ImageHash(cpu::RenderOnCpu(BuildDrawList(scene))) == hash);
      });
  REQUIRE(checked == before.size());  // every recorded scene is still shipped, and was checked
}
