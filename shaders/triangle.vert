// Transforms a model-space vertex to clip space with the instance's matrix F (DrawCall::F).
// Compiled twice (shaders/CMakeLists.txt): as it stands, F arrives as a push constant per draw
// (the chapter's Listing 10-5, one draw per instance); with INSTANCED defined, F arrives as a
// per-instance vertex attribute, for one draw of many instances. The arithmetic is the same.
#version 450

layout(location = 0) in vec3 p;  // the model-space position; colours are per triangle

// Shared with triangle.frag and src/gpu/pipeline.hpp (PushConstants): 68 bytes.
layout(push_constant) uniform Push {
  mat4 F;            // column-major: F[i] is column i (unused when INSTANCED)
  uint first_colour; // used by the fragment shader
} push;

#ifdef INSTANCED
layout(location = 1) in mat4 instance_F;  // locations 1-4, one column each, advanced per instance
#endif

// precise: the SPIR-V gets NoContraction on every multiply and add below, so no compiler may fuse
// them into FMAs or reorder the sum. The CPU twin (src/cpu/) must compute exactly this, in float,
// componentwise and in this order:
//   gl_Position = ((F[0] * p.x + F[1] * p.y) + F[2] * p.z) + F[3]
// F[3] is added, not multiplied by w = 1 (x * 1 is exact anyway, but the sum's order is not free).
precise gl_Position;

void main() {
#ifdef INSTANCED
  const mat4 F = instance_F;
#else
  const mat4 F = push.F;
#endif
  gl_Position = ((F[0] * p.x + F[1] * p.y) + F[2] * p.z) + F[3];
}
