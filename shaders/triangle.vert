// Transforms a model-space vertex to clip space with the instance's matrix F (DrawCall::F), and
// names the triangle it is a corner of, for the fragment shader's colour.
// Compiled twice (shaders/CMakeLists.txt): as it stands, F arrives as a push constant per draw
// (the chapter's Listing 10-5, one draw per instance); with INSTANCED defined, F arrives as a
// per-instance vertex attribute, for one draw of many instances. The arithmetic is the same.
#version 450

layout(location = 0) in vec3 p;  // the model-space position of one corner of one triangle

// Shared with src/gpu/pipeline.hpp (PushConstants): 64 bytes.
layout(push_constant) uniform Push {
  mat4 F;  // column-major: F[i] is column i (unused when INSTANCED)
} push;

#ifdef INSTANCED
layout(location = 1) in mat4 instance_F;  // locations 1-4, one column each, advanced per instance
#endif

// The vertex buffer holds every triangle's three corners in turn, mesh after mesh
// (src/gpu/mesh_buffers.hpp), so corner v is a corner of triangle v / 3 of the whole list, which
// is where its colour is. Flat: the same number at every fragment, even of a clipped triangle.
// (Reading gl_PrimitiveID in the fragment shader instead costs lavapipe a primitive-assembly
// pass with allocations per instance: a third of its time on a million cubes.)
layout(location = 0) flat out uint triangle;

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
  triangle = uint(gl_VertexIndex) / 3u;
}
