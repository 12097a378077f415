// Records a frame's draws into a command buffer inside its render pass: the DrawPlan's batches in
// list order, binding a pipeline, an instance buffer or a descriptor set only when it changes. It
// does not begin or end the render pass or the command buffer, and owns no Vulkan object.
#pragma once

#include "chain/draw_list.hpp"
#include "gpu/draw_batches.hpp"
#include "gpu/instance_buffers.hpp"
#include "gpu/mesh_buffers.hpp"
#include "gpu/pipeline.hpp"

#include <vulkan/vulkan_raii.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <tuple>

namespace twinraster::gpu {

class DrawRecorder {
 public:
  // `colour_set` serves unlit draws, `lit_set` lit ones (Pipeline::set_layout); every argument
  // must outlive the recorder.
  DrawRecorder(const vk::raii::CommandBuffer& cmd, Pipeline& pipeline, const DrawList& list, const MeshBuffers& meshes,
               const InstanceBuffers& instances, vk::DescriptorSet colour_set, vk::DescriptorSet lit_set);

  void Record(const DrawBatch& batch);
  std::size_t draw_commands() const { return draw_commands_; }  // vkCmdDraw calls so far

 private:
  void BindPipeline(Shading shading, bool vertex_colours, FSource source);
  void RecordUnlit(const DrawBatch& batch, const MeshRange& range, vk::PipelineLayout layout);
  void RecordLit(const DrawBatch& batch, const MeshRange& range, vk::PipelineLayout layout);
  void Draw(const MeshRange& range, std::uint32_t instances, std::uint32_t first_instance);

  const vk::raii::CommandBuffer& cmd_;
  Pipeline& pipeline_;
  const DrawList& list_;
  const MeshBuffers& meshes_;
  const InstanceBuffers& instances_;
  vk::DescriptorSet colour_set_, lit_set_;

  std::optional<std::tuple<Shading, bool, FSource>> bound_pipeline_;
  // The descriptor set bound: none yet, the unlit one, or the lit one showing LitInstance range k.
  static constexpr std::int64_t kNoSet = -2, kUnlitSet = -1;
  std::int64_t bound_set_ = kNoSet;
  std::optional<std::uint32_t> bound_buffer_;
  std::size_t draw_commands_ = 0;
};

}  // namespace twinraster::gpu
