// Colours each fragment with its triangle's flat colour from the colour storage buffer.
#version 450

// Shared with triangle.vert and src/gpu/pipeline.hpp (PushConstants): 68 bytes.
layout(push_constant) uniform Push {
  mat4 F;             // used by the vertex shader
  uint first_colour;  // where this draw's mesh starts in `colours`
} push;

// One packed RGBA8 per triangle, all meshes concatenated; red in the lowest byte.
layout(std430, set = 0, binding = 0) readonly buffer Colours {
  uint rgba8[];
} colours;

layout(location = 0) out vec4 colour;

void main() {
  // gl_PrimitiveID counts the triangles of this draw from 0 (so a triangle clipped into several
  // keeps its number). Reading it in a fragment shader needs the Geometry capability, hence the
  // device feature geometryShader. k / 255 survives the UNORM8 output exactly as k.
  uint packed = colours.rgba8[push.first_colour + uint(gl_PrimitiveID)];
  colour = vec4(unpackUnorm4x8(packed).rgb, 1.0);
}
