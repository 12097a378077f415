// Transforms a model-space vertex to clip space with the instance's matrix F (DrawCall::F).
#version 450

layout(location = 0) in vec3 p;  // the only vertex attribute; colours are per triangle

// Shared with triangle.frag and src/gpu/pipeline.hpp (PushConstants): 68 bytes.
layout(push_constant) uniform Push {
  mat4 F;            // column-major: F[i] is column i
  uint first_colour; // used by the fragment shader
} push;

// precise: the SPIR-V gets NoContraction on every multiply and add below, so no compiler may fuse
// them into FMAs or reorder the sum. The CPU twin (src/cpu/) must compute exactly this, in float,
// componentwise and in this order:
//   gl_Position = ((F[0] * p.x + F[1] * p.y) + F[2] * p.z) + F[3]
// F[3] is added, not multiplied by w = 1 (x * 1 is exact anyway, but the sum's order is not free).
precise gl_Position;

void main() {
  gl_Position = ((push.F[0] * p.x + push.F[1] * p.y) + push.F[2] * p.z) + push.F[3];
}
