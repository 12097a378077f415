// Colours each fragment: unlit, with its triangle's flat colour from the colour storage buffer;
// with LIT defined, with the colour the vertex shader lit (FLAT: the provoking vertex's; else
// interpolated perspective-correctly between the corners). The LIT, not FLAT, variant also serves
// unlit vertex colours: triangle.vert with VERTEX_COLOURS hands it k / 255 to interpolate alike.
#version 450

#ifdef LIT
#ifdef FLAT
layout(location = 0) flat in vec3 lit;
#else
layout(location = 0) in vec3 lit;
#endif
#else
// One packed RGBA8 per triangle, all meshes concatenated; red in the lowest byte.
layout(std430, set = 0, binding = 0) readonly buffer Colours {
  uint rgba8[];
} colours;

layout(location = 0) flat in uint triangle;  // from triangle.vert: the index of the colour
#endif

layout(location = 0) out vec4 colour;

void main() {
#ifdef LIT
  colour = vec4(lit, 1.0);
#else
  // k / 255 survives the UNORM8 output exactly as k.
  colour = vec4(unpackUnorm4x8(colours.rgba8[triangle]).rgb, 1.0);
#endif
}
