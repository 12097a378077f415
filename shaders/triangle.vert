// Transforms a model-space vertex to clip space with the instance's matrix F (DrawCall::F), and
// names the triangle it is a corner of, for the fragment shader's colour.
// Compiled several times (shaders/CMakeLists.txt): as it stands, F arrives as a push constant per
// draw (the chapter's Listing 10-5, one draw per instance); with INSTANCED defined, F arrives as a
// per-instance vertex attribute, for one draw of many instances. The arithmetic is the same.
// With LIT defined, the vertex is also lit (Computer Graphics from Scratch's diffuse model) and
// passes its colour on: flat (FLAT, the provoking vertex's colour fills the triangle) or smooth
// (Gouraud, interpolated perspective-correctly).
// With VERTEX_COLOURS defined, each corner brings its vertex's own colour (DrawMesh::vertex_colours)
// as an attribute: lit, it is the base colour in place of the triangle's; unlit, the vertex passes
// k / 255 on, interpolated perspective-correctly (the fragment shader is lit_gouraud.frag's).
#version 450

layout(location = 0) in vec3 p;  // the model-space position of one corner of one triangle

#ifdef LIT
// Shared with src/gpu/pipeline.hpp (LitPushConstants): 68 bytes. `draw` + gl_InstanceIndex is
// the draw's index in DrawList::draws, where its LitInstance is.
layout(push_constant) uniform Push {
  mat4 F;  // column-major: F[i] is column i (unused when INSTANCED)
  uint draw;
} push;
#else
// Shared with src/gpu/pipeline.hpp (PushConstants): 64 bytes.
layout(push_constant) uniform Push {
  mat4 F;  // column-major: F[i] is column i (unused when INSTANCED)
} push;
#endif

#ifdef INSTANCED
layout(location = 1) in mat4 instance_F;  // locations 1-4, one column each, advanced per instance
#endif

#ifdef VERTEX_COLOURS
// The corner's vertex colour, packed RGBA8 with red in the lowest byte (src/gpu/mesh_buffers.hpp).
layout(location = 6) in uint vertex_rgba;

// k / 255 per channel: the lit base colour's divide, shared so that both read a colour alike. The
// CPU twin: cpu::BaseColour (src/cpu/lighting.hpp).
vec3 BaseColour(uint rgba) {
  precise vec3 base = vec3(float(rgba & 255u), float((rgba >> 8) & 255u), float((rgba >> 16) & 255u)) / 255.0;
  return base;
}
#endif

// precise: the SPIR-V gets NoContraction on every multiply and add below, so no compiler may fuse
// them into FMAs or reorder the sum. The CPU twin (src/cpu/) must compute exactly this, in float,
// componentwise and in this order:
//   gl_Position = ((F[0] * p.x + F[1] * p.y) + F[2] * p.z) + F[3]
// F[3] is added, not multiplied by w = 1 (x * 1 is exact anyway, but the sum's order is not free).
precise gl_Position;

#ifdef LIT
layout(location = 5) in vec3 normal;  // the corner's model-space unit normal (DrawMesh::normals)

// One packed RGBA8 base colour per triangle, all meshes concatenated; red in the lowest byte.
layout(std430, set = 0, binding = 0) readonly buffer Colours {
  uint rgba8[];
} colours;

// DrawLighting::instances, one per draw (src/gpu/light_buffers.hpp writes this layout).
struct LitInstance {
  mat4x3 model;  // the upper three rows of M_Model
  mat3 normal;   // N = (M_Model's upper 3x3)^-T
};
layout(std430, set = 0, binding = 1) readonly buffer Instances {
  LitInstance instance[];
} instances;

struct Light {
  vec3 vector;  // directional: toward the light; point: its position (world space)
  float intensity;
  uint point;
};
layout(std430, set = 0, binding = 2) readonly buffer Lights {
  float ambient;
  uint count;
  Light light[];
} lights;

#ifdef FLAT
layout(location = 0) flat out vec3 lit;
#else
layout(location = 0) out vec3 lit;
#endif

// The light at one vertex, in world space. The CPU twin (src/cpu/lighting.cpp) computes the same
// operations in the same order; each is one IEEE float operation on lavapipe.
vec3 LightVertex(uint draw, uint triangle) {
  const LitInstance at = instances.instance[draw];
  precise vec3 world = ((at.model[0] * p.x + at.model[1] * p.y) + at.model[2] * p.z) + at.model[3];
  precise vec3 n = (at.normal[0] * normal.x + at.normal[1] * normal.y) + at.normal[2] * normal.z;
  // Renormalised, so the book's division by |n| drops out: I = ambient + sum i * n.l / |l|.
  precise float n_length = sqrt((n.x * n.x + n.y * n.y) + n.z * n.z);
  n = n / n_length;
  precise float intensity = lights.ambient;
  for (uint i = 0u; i < lights.count; ++i) {
    const Light light = lights.light[i];
    precise vec3 l = light.point != 0u ? light.vector - world : light.vector;
    precise float n_dot_l = (n.x * l.x + n.y * l.y) + n.z * l.z;
    if (n_dot_l > 0.0) {
      precise float l_length = sqrt((l.x * l.x + l.y * l.y) + l.z * l.z);
      intensity = intensity + light.intensity * (n_dot_l / l_length);
    }
  }
#ifdef VERTEX_COLOURS
  precise vec3 base = BaseColour(vertex_rgba);  // this corner's own colour; `triangle` is unused
#else
  const uint rgba = colours.rgba8[triangle];
  precise vec3 base = vec3(float(rgba & 255u), float((rgba >> 8) & 255u), float((rgba >> 16) & 255u)) / 255.0;
#endif
  precise vec3 colour = base * min(intensity, 1.0);
  return colour;
}
#elif defined(VERTEX_COLOURS)
// Unlit: the vertex's colour, interpolated perspective-correctly as a Gouraud colour is.
layout(location = 0) out vec3 colour;
#else
// The vertex buffer holds every triangle's three corners in turn, mesh after mesh
// (src/gpu/mesh_buffers.hpp), so corner v is a corner of triangle v / 3 of the whole list, which
// is where its colour is. Flat: the same number at every fragment, even of a clipped triangle.
// (Reading gl_PrimitiveID in the fragment shader instead costs lavapipe a primitive-assembly
// pass with allocations per instance: a third of its time on a million cubes.)
layout(location = 0) flat out uint triangle;
#endif

void main() {
#ifdef INSTANCED
  const mat4 F = instance_F;
#else
  const mat4 F = push.F;
#endif
  gl_Position = ((F[0] * p.x + F[1] * p.y) + F[2] * p.z) + F[3];
#ifdef LIT
  lit = LightVertex(push.draw + uint(gl_InstanceIndex), uint(gl_VertexIndex) / 3u);
#elif defined(VERTEX_COLOURS)
  colour = BaseColour(vertex_rgba);
#else
  triangle = uint(gl_VertexIndex) / 3u;
#endif
}
