// Malformed inputs are std::invalid_argument, as for the twin.
#include "support/catch.hpp"
#include "truth_test_support.hpp"

#include <stdexcept>

using namespace twinraster;
using namespace twinraster::truthtest;

TEST_CASE("RenderTruth: malformed lists and clip positions throw", "[truth][errors]") {
  const ClipTriangle t{{glm::dvec4{-1, -1, 0.5, 1}, glm::dvec4{1, -1, 0.5, 1}, glm::dvec4{0, 1, 0.5, 1}}};
  const TruthInput good = MakeInput(8, 8, {t});
  REQUIRE_NOTHROW(Render(good));

  auto broken = [&](auto&& change) {
    TruthInput in = good;
    change(in);
    return in;
  };
  CHECK_THROWS_AS(Render(broken([](TruthInput& in) { in.list.width = 0; })), std::invalid_argument);
  CHECK_THROWS_AS(Render(broken([](TruthInput& in) { in.list.height = 16385; })), std::invalid_argument);
  CHECK_THROWS_AS(Render(broken([](TruthInput& in) { in.list.draws[0].mesh = 1; })), std::invalid_argument);
  CHECK_THROWS_AS(Render(broken([](TruthInput& in) { in.list.meshes[0].triangles[0][2] = 3; })), std::invalid_argument);
  CHECK_THROWS_AS(Render(broken([](TruthInput& in) { in.list.meshes[0].colours.clear(); })), std::invalid_argument);
  CHECK_THROWS_AS(Render(broken([](TruthInput& in) { in.clip.clear(); })), std::invalid_argument);
  CHECK_THROWS_AS(Render(broken([](TruthInput& in) { in.clip[0].pop_back(); })), std::invalid_argument);
  CHECK_THROWS_AS(Render(broken([](TruthInput& in) { in.clip.push_back(in.clip[0]); })), std::invalid_argument);
}
