// Planning draws: runs of one mesh become instanced batches when long enough (or always, or
// never), in list order, and instance buffers split where they fill.
#include "gpu/draw_batches.hpp"

#include "support/catch.hpp"

using namespace twinraster;
using gpu::DrawBatch;
using gpu::Instancing;

namespace {

DrawList ListOfMeshes(const std::vector<std::uint32_t>& meshes) {
  DrawList list;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    glm::mat4 f(1.0f);
    f[3][0] = static_cast<float>(i);  // each draw's F is recognisable by its index
    list.draws.push_back(DrawCall{meshes[i], f});
  }
  return list;
}

// Every draw is covered once, in order, by batches of one mesh.
void RequireCoversInOrder(const DrawList& list, const gpu::DrawPlan& plan) {
  std::size_t next = 0;
  for (const DrawBatch& b : plan.batches) {
    REQUIRE(b.first_draw == next);
    REQUIRE(b.count > 0);
    for (std::size_t d = b.first_draw; d < b.first_draw + b.count; ++d) REQUIRE(list.draws[d].mesh == b.mesh);
    next += b.count;
  }
  REQUIRE(next == list.draws.size());
}

}  // namespace

TEST_CASE("PlanDraws kNever: one per-draw batch per run of a mesh", "[gpu][batches]") {
  const DrawList list = ListOfMeshes({0, 0, 1, 0, 0, 0});
  const gpu::DrawPlan plan = gpu::PlanDraws(list, Instancing::kNever);
  RequireCoversInOrder(list, plan);
  REQUIRE(plan.batches.size() == 3);
  for (const DrawBatch& b : plan.batches) REQUIRE_FALSE(b.instanced);
  REQUIRE(plan.buffer_sizes.empty());
}

TEST_CASE("PlanDraws kAuto: only runs of at least kInstancingThreshold are instanced", "[gpu][batches]") {
  std::vector<std::uint32_t> meshes(gpu::kInstancingThreshold, 0);  // a long run of mesh 0
  meshes.push_back(1);                                              // one draw of mesh 1
  meshes.insert(meshes.end(), gpu::kInstancingThreshold - 1, 0);    // a short run of mesh 0
  const DrawList list = ListOfMeshes(meshes);
  const gpu::DrawPlan plan = gpu::PlanDraws(list, Instancing::kAuto);
  RequireCoversInOrder(list, plan);
  REQUIRE(plan.batches.size() == 3);
  REQUIRE(plan.batches[0].instanced);
  REQUIRE_FALSE(plan.batches[1].instanced);
  REQUIRE_FALSE(plan.batches[2].instanced);
  REQUIRE(plan.buffer_sizes == std::vector<std::uint32_t>{gpu::kInstancingThreshold});
}

TEST_CASE("PlanDraws kAlways: instance buffers fill in order and runs split across them", "[gpu][batches]") {
  const DrawList list = ListOfMeshes({0, 0, 0, 1, 1, 1, 1, 1, 0});
  const gpu::DrawPlan plan = gpu::PlanDraws(list, Instancing::kAlways, 4);
  RequireCoversInOrder(list, plan);
  REQUIRE(plan.buffer_sizes == std::vector<std::uint32_t>{4, 4, 1});
  // Mesh 0 x3 -> buffer 0 [0, 3); mesh 1 x5 -> buffer 0 [3, 4) then buffer 1 [0, 4); mesh 0 -> buffer 2.
  const std::vector<std::array<std::uint32_t, 3>> expected = {{0, 0, 3}, {0, 3, 1}, {1, 0, 4}, {2, 0, 1}};
  REQUIRE(plan.batches.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    INFO("batch " << i);
    REQUIRE(plan.batches[i].instanced);
    REQUIRE(plan.batches[i].buffer == expected[i][0]);
    REQUIRE(plan.batches[i].first_instance == expected[i][1]);
    REQUIRE(plan.batches[i].count == expected[i][2]);
  }
}

TEST_CASE("PlanDraws: an empty list plans nothing, a zero buffer size is refused", "[gpu][batches]") {
  REQUIRE(gpu::PlanDraws(DrawList{}, Instancing::kAlways).batches.empty());
  REQUIRE_THROWS_AS(gpu::PlanDraws(ListOfMeshes({0}), Instancing::kAlways, 0), std::invalid_argument);
}
