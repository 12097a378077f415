// Scenes without lighting are untouched by the truth's light: its image of every unlit shipped
// scene has the same bytes as before the truth learnt light. The hashes were recorded from the
// build of commit 43c77f2 (the truth's code then was as it stayed until lighting; FNV-1a, 64 bits,
// over the RGBA bytes of RenderTruth(BuildDrawList(scene), ExactClipSpace(scene)), drawn filled
// as the bench draws it).
#include "chain/draw_list.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/image_hashes.hpp"
#include "truth/truth_renderer.hpp"

#include <map>
#include <string>

using namespace twinraster;

TEST_CASE("Truth: unlit scenes render byte for byte as before the truth learnt light", "[truth][lighting]") {
  const std::map<std::string, std::uint64_t> before = {
      {"bench/spheres-100k", 0x1cb64a50c9114e0dull},
      {"catlike-grid", 0x8f5dfba555df2472ull},
      {"catlike-orthographic", 0x4faa669895d30bdbull},
      {"catlike-rotations", 0x05af40e6cb918599ull},
      {"cgfs-figure-10-4", 0x9b99161ba8782c08ull},
      {"cgfs-figure-10-5", 0xdc68e08f759c596aull},
      {"cgfs-instances", 0xa03969e938d4f8a4ull},
      {"cgfs-scene", 0xfa1279a750a1e2a5ull},
      {"cgfs-transforms", 0x7855b5ba966a0f61ull},
      {"hard/accumulated-rotation", 0xb45dfb89067937d8ull},
      {"hard/accumulated-rotation-reorthonormalized", 0xb45dfb89067937d8ull},
      {"hard/camera-inside-cube", 0xb0f7c7e3f0fe0369ull},
      {"hard/degenerate", 0xec29f73bd4b14325ull},
      {"hard/depth-ratio-1e-1", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-1-reversed", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-2", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-2-reversed", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-3", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-3-reversed", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-4", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-4-reversed", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-5", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-5-reversed", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-6", 0x72e2b4984dce7de1ull},
      {"hard/depth-ratio-1e-6-reversed", 0x72e2b4984dce7de1ull},
      {"hard/extreme-scales", 0x12f7eb3816f1656dull},
      {"hard/far-1e3", 0x1629adf88fa2dbb5ull},
      {"hard/far-1e5", 0x1629adf88fa2dbb5ull},
      {"hard/far-1e7", 0x1629adf88fa2dbb5ull},
      {"hard/near-plane", 0xc9d1eb1617a6a4e9ull},
      {"hard/orthographic-edge-on", 0xa31452dda2d79823ull},
      {"hard/orthographic-near-far", 0xea923dcec436427bull},
      {"hard/orthographic-near-far-reversed", 0xea923dcec436427bull},
      {"hard/up-near-parallel", 0xdd64e50bcb2cffe6ull},
      {"hard/zero-negative-scale", 0xf8396ca81a4f80f3ull},
      {"lookat", 0x228471f6469ca600ull},
  };
  const std::size_t checked = test::ForEachRecordedScene(
      before, [](const std::filesystem::path& file, const std::string& name, std::uint64_t hash) {
        INFO(name);
        Scene scene = LoadScene(file);
        REQUIRE_FALSE(scene.lighting.has_value());
        scene.wireframe = false;  // the truth draws filled triangles only
        const DrawList list = BuildDrawList(scene);
        const truth::ExactClipPositions clip = truth::ExactClipSpace(scene);
        CHECK(test::ImageHash(truth::RenderTruth(list, clip)) == hash);
        // Neither a light (which lights nothing here) nor asking for the surfaces changes a byte.
        const truth::ExactLight light(scene);
        const truth::TruthImage with_surfaces = truth::RenderTruthSurfaces(list, clip, &light);
        CHECK(test::ImageHash(with_surfaces.image) == hash);
        CHECK(with_surfaces.surfaces.size() == std::size_t{list.width} * list.height);
      });
  REQUIRE(checked == before.size());  // every recorded scene is still shipped, and was checked
}
