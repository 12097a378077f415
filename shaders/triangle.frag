// Colours each fragment with its triangle's flat colour from the colour storage buffer.
#version 450

// One packed RGBA8 per triangle, all meshes concatenated; red in the lowest byte.
layout(std430, set = 0, binding = 0) readonly buffer Colours {
  uint rgba8[];
} colours;

layout(location = 0) flat in uint triangle;  // from triangle.vert: the index of the colour

layout(location = 0) out vec4 colour;

void main() {
  // k / 255 survives the UNORM8 output exactly as k.
  colour = vec4(unpackUnorm4x8(colours.rgba8[triangle]).rgb, 1.0);
}
