// The verifier's fast paths (draws and tiles skipped by their boxes and depth ranges) give exactly
// the judgement of testing every primitive and pixel one by one: each pixel's class, the counts,
// and the first and worst violation with the colours allowed there, on the twin's image and on the
// same image shifted by one pixel (which fails), for random and shipped scenes.
#include "cpu/cpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "verify/verifier.hpp"
#include "verify_scenes.hpp"

#include <cstdint>
#include <string>

using namespace twinraster;

namespace {

void CheckSameViolation(const std::optional<verify::Violation>& fast, const std::optional<verify::Violation>& slow) {
  REQUIRE(fast.has_value() == slow.has_value());
  if (!fast) return;
  CHECK(fast->x == slow->x);
  CHECK(fast->y == slow->y);
  CHECK(fast->colour == slow->colour);
  CHECK(fast->distance == slow->distance);
  CHECK(fast->allowed == slow->allowed);
}

// Judges `image` both ways under `rules` and requires the same judgement; returns its violations.
std::uint64_t CheckSameJudgement(const test::Drawn& drawn, const Image& image, verify::VerifyOptions rules) {
  rules.fast_paths = true;
  const verify::Verification fast = verify::VerifyImage(drawn.scene, drawn.list, image, rules);
  rules.fast_paths = false;
  const verify::Verification slow = verify::VerifyImage(drawn.scene, drawn.list, image, rules);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < fast.pixels.size(); ++i) differing += fast.pixels[i] != slow.pixels[i];
  CHECK(fast.pixels.size() == slow.pixels.size());
  CHECK(differing == 0);
  CHECK(fast.certain == slow.certain);
  CHECK(fast.uncertain == slow.uncertain);
  CHECK(fast.violations == slow.violations);
  CHECK(fast.covered == slow.covered);
  CHECK(fast.uncertain_shared_edges == slow.uncertain_shared_edges);
  CHECK(fast.background_excluded == slow.background_excluded);
  CheckSameViolation(fast.first, slow.first);
  CheckSameViolation(fast.worst, slow.worst);
  return fast.violations;
}

void CheckBothImages(const test::Drawn& drawn, int& failing) {
  const Image image = cpu::RenderOnCpu(drawn.list);
  const Image shifted = ShiftedRight(image);
  for (const verify::VerifyOptions rules : {verify::VerifyOptions{8, true}, verify::VerifyOptions{4, false}}) {
    CheckSameJudgement(drawn, image, rules);
    failing += CheckSameJudgement(drawn, shifted, rules) > 0;
  }
}

}  // namespace

TEST_CASE("verify: the fast paths judge 200 random scenes exactly as testing every pixel does", "[verify][random]") {
  int failing = 0;
  for (std::uint32_t seed = 1; seed <= 100; ++seed) {
    for (const bool wireframe : {false, true}) {
      INFO("seed " << seed << (wireframe ? " --wireframe" : ""));
      CheckBothImages(test::RandomScene(seed, wireframe), failing);
    }
  }
  CHECK(failing >= 200);  // the shifted images mostly fail: the violation paths are compared too
}

TEST_CASE("verify: the fast paths judge every shipped scene exactly as testing every pixel does", "[verify]") {
  int failing = 0;
  for (const auto& file : test::ShippedScenesAndMeshes()) {
    for (const bool wireframe : {false, true}) {
      INFO(file.string() << (wireframe ? " --wireframe" : ""));
      CheckBothImages(test::ShippedScene(file, wireframe), failing);
    }
  }
  CHECK(failing > 0);
}
