#include "gpu/draw_recorder.hpp"

#include "gpu/light_buffers.hpp"

#include <algorithm>

namespace twinraster::gpu {

DrawRecorder::DrawRecorder(const vk::raii::CommandBuffer& cmd, Pipeline& pipeline, const DrawList& list,
                           const MeshBuffers& meshes, const InstanceBuffers& instances, vk::DescriptorSet colour_set,
                           vk::DescriptorSet lit_set)
    : cmd_(cmd),
      pipeline_(pipeline),
      list_(list),
      meshes_(meshes),
      instances_(instances),
      colour_set_(colour_set),
      lit_set_(lit_set) {}

// In list order: the depth test is strict (LESS, or GREATER with reversed Z), so the earlier of two
// equally deep fragments stays. An instanced draw keeps that order too: its instances are
// rasterized in instance order.
void DrawRecorder::Record(const DrawBatch& batch) {
  const MeshRange& range = meshes_.range(batch.mesh);
  if (range.corner_count == 0) return;  // a mesh without triangles draws nothing
  const FSource source = batch.instanced ? FSource::kInstanceAttribute : FSource::kPushConstant;
  const Shading shading = list_.meshes[batch.mesh].shading;
  const bool lit = shading != Shading::kUnlit;
  const vk::PipelineLayout layout = *pipeline_.layout(lit);
  BindPipeline(shading, !list_.meshes[batch.mesh].vertex_colours.empty(), source);
  if (batch.instanced && bound_buffer_ != batch.buffer) {
    cmd_.bindVertexBuffers(1, instances_.buffer(batch.buffer), vk::DeviceSize{0});
    bound_buffer_ = batch.buffer;
  }
  if (lit) {
    RecordLit(batch, range, layout);
  } else {
    RecordUnlit(batch, range, layout);
  }
}

void DrawRecorder::BindPipeline(Shading shading, bool vertex_colours, FSource source) {
  const std::tuple key{shading, vertex_colours, source};
  if (bound_pipeline_ == key) return;
  cmd_.bindPipeline(vk::PipelineBindPoint::eGraphics,
                    *pipeline_.pipeline(shading, vertex_colours, source, list_.reversed_z, list_.wireframe));
  bound_pipeline_ = key;
}

void DrawRecorder::RecordUnlit(const DrawBatch& batch, const MeshRange& range, vk::PipelineLayout layout) {
  if (bound_set_ != kUnlitSet) {
    // The lit and unlit layouts differ, so switching between them unbinds the set.
    cmd_.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, layout, 0, colour_set_, nullptr);
    bound_set_ = kUnlitSet;
  }
  if (batch.instanced) {
    Draw(range, batch.count, batch.first_instance);
    return;
  }
  for (std::uint32_t i = 0; i < batch.count; ++i) {
    const PushConstants push{.F = list_.draws[batch.first_draw + i].F};
    cmd_.pushConstants<PushConstants>(layout, vk::ShaderStageFlagBits::eVertex, 0, push);
    Draw(range, 1, 0);
  }
}

// The shader finds a draw's LitInstance at push.draw + gl_InstanceIndex within the bound range, so
// a batch is drawn in pieces that do not cross a range's end.
void DrawRecorder::RecordLit(const DrawBatch& batch, const MeshRange& range, vk::PipelineLayout layout) {
  for (std::uint32_t drawn = 0; drawn < batch.count;) {
    const std::size_t d = batch.first_draw + drawn;
    const auto lit_range = static_cast<std::uint32_t>(d / kLitInstancesPerRange);
    const std::size_t range_end = std::size_t{lit_range + 1} * kLitInstancesPerRange;
    // The binding shows kLitInstancesPerRange draws from range_begin; the last range's window is
    // moved back to end with the buffer (an offset plus the range may not pass its end).
    const std::size_t range_begin = std::min<std::size_t>(
        std::size_t{lit_range} * kLitInstancesPerRange,
        list_.draws.size() > kLitInstancesPerRange ? list_.draws.size() - kLitInstancesPerRange : 0);
    const auto n = static_cast<std::uint32_t>(std::min<std::size_t>(batch.count - drawn, range_end - d));
    if (bound_set_ != std::int64_t{lit_range}) {
      const auto offset = static_cast<std::uint32_t>(range_begin * kLitInstanceBytes);
      cmd_.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, layout, 0, lit_set_, offset);
      bound_set_ = lit_range;
    }
    if (batch.instanced) {
      // gl_InstanceIndex counts from firstInstance: the offset makes the sum the draw's index in
      // the range (unsigned arithmetic wraps, in C++ and in GLSL alike).
      const std::uint32_t first_instance = batch.first_instance + drawn;
      const LitPushConstants push{.F = glm::mat4(1.0f),
                                  .draw = static_cast<std::uint32_t>(d - range_begin) - first_instance};
      cmd_.pushConstants<LitPushConstants>(layout, vk::ShaderStageFlagBits::eVertex, 0, push);
      Draw(range, n, first_instance);
    } else {
      for (std::uint32_t i = 0; i < n; ++i) {
        const LitPushConstants push{.F = list_.draws[d + i].F, .draw = static_cast<std::uint32_t>(d + i - range_begin)};
        cmd_.pushConstants<LitPushConstants>(layout, vk::ShaderStageFlagBits::eVertex, 0, push);
        Draw(range, 1, 0);
      }
    }
    drawn += n;
  }
}

void DrawRecorder::Draw(const MeshRange& range, std::uint32_t instances, std::uint32_t first_instance) {
  cmd_.draw(range.corner_count, instances, range.first_corner, first_instance);
  ++draw_commands_;
}

}  // namespace twinraster::gpu
