#include "variants.hpp"

#include "cpu/cpu_renderer.hpp"
#include "truth/truth_renderer.hpp"

#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace twinraster::test {

namespace {

// The vertex stage as the twin's: F · (p, 1) in float, per draw.
cpu::ClipPositions VertexStage(const DrawList& list) {
  cpu::ClipPositions clip;
  for (const DrawCall& draw : list.draws) {
    std::vector<glm::vec4>& out = clip.emplace_back();
    for (const glm::vec3& p : list.meshes[draw.mesh].positions) out.push_back(draw.F * glm::vec4(p, 1.0f));
  }
  return clip;
}

// Moves every vertex in the framebuffer: window (x, y) -> move(x, y), for vertices in front of the
// camera (w > 0), computed in double and written back to clip space.
template <class Move>
cpu::ClipPositions InWindow(const DrawList& list, Move&& move) {
  cpu::ClipPositions clip = VertexStage(list);
  const double hw = list.width / 2.0, hh = list.height / 2.0;
  for (auto& draw : clip) {
    for (glm::vec4& c : draw) {
      if (!(c.w > 0)) continue;
      const glm::dvec2 window((double(c.x) / c.w + 1) * hw, (double(c.y) / c.w + 1) * hh);
      const glm::dvec2 moved = move(window);
      c.x = float((moved.x / hw - 1) * c.w);
      c.y = float((moved.y / hh - 1) * c.w);
    }
  }
  return clip;
}

Image Rasterize(const DrawList& list, const cpu::ClipPositions& clip, cpu::RasterRules rules = {}) {
  cpu::CpuOptions options;
  options.rules = rules;
  return cpu::RasterizeClipSpace(list, clip, options);
}

Image RenderWith(const DrawList& list, cpu::RasterRules rules) {
  cpu::CpuOptions options;
  options.rules = rules;
  return cpu::RenderOnCpu(list, options);
}

Image Rotated180(const Image& image) {
  Image out(image.width, image.height);
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      std::copy_n(image.pixel(x, y), 4, out.pixel(image.width - 1 - x, image.height - 1 - y));
    }
  }
  return out;
}

Image FlippedRows(const Image& image) {
  Image out(image.width, image.height);
  for (std::uint32_t y = 0; y < image.height; ++y)
    std::copy_n(image.pixel(0, y), image.width * 4, out.pixel(0, image.height - 1 - y));
  return out;
}

// Every drawn pixel (not the background) also paints its right and lower neighbours where they
// show the background: lines two pixels wide, triangles a pixel too big.
Image Grown(const Image& image, Rgb8 background) {
  const auto is_background = [&](const std::uint8_t* p) {
    return p[0] == background.r && p[1] == background.g && p[2] == background.b;
  };
  Image out = image;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (is_background(p)) continue;
      if (x + 1 < image.width && is_background(image.pixel(x + 1, y))) std::copy_n(p, 4, out.pixel(x + 1, y));
      if (y + 1 < image.height && is_background(image.pixel(x, y + 1))) std::copy_n(p, 4, out.pixel(x, y + 1));
    }
  }
  return out;
}

// Rotates each flat-lit triangle's corners (a, b, c) -> (b, c, a), with their normals.
DrawList CornersRotated(DrawList list) {
  for (DrawMesh& mesh : list.meshes) {
    if (mesh.shading != Shading::kFlat) continue;
    for (auto& t : mesh.triangles) t = {t[1], t[2], t[0]};
    for (auto& n : mesh.normals) n = {n[1], n[2], n[0]};
  }
  return list;
}

}  // namespace

Image DrawTwin(const DrawList& list) { return cpu::RenderOnCpu(list); }

std::vector<TwinVariant> ConformantVariants() {
  std::vector<TwinVariant> v;
  v.push_back({"4 subpixel bits",
               true,
               4,
               false,
               [](const Scene&, const DrawList& list) {
                 // Snapped to the 1/16 grid first: the twin's own 1/256 snapping then keeps it.
                 return Rasterize(
                     list, InWindow(list, [](glm::dvec2 p) { return glm::round((p - 0.5) * 16.0) / 16.0 + 0.5; }));
               },
               {}});
  v.push_back({"the other tie rule (bottom-right)",
               true,
               8,
               false,
               [](const Scene&, const DrawList& list) {
                 // Drawn turned by 180 degrees and turned back: top-left ties become bottom-right.
                 cpu::ClipPositions clip = VertexStage(list);
                 for (auto& draw : clip) {
                   for (glm::vec4& c : draw) c.x = -c.x, c.y = -c.y;
                 }
                 return Rotated180(Rasterize(list, clip));
               },
               {}});
  v.push_back({"coverage, depth and colour in double (the truth's rasterizer)",
               true,
               8,
               true,
               [](const Scene& scene, const DrawList& list) {
                 truth::ExactClipPositions clip;
                 for (const DrawCall& draw : list.draws) {
                   auto& out = clip.emplace_back();
                   for (const glm::vec3& p : list.meshes[draw.mesh].positions) {
                     out.push_back(glm::dmat4(draw.F) * glm::dvec4(glm::dvec3(p), 1.0));
                   }
                 }
                 const truth::ExactLight light(scene);
                 return truth::RenderTruth(list, clip, &light);
               },
               {}});
  v.push_back({"no FMA (lavapipe's sse4.1 arithmetic)",
               true,
               8,
               false,
               [](const Scene&, const DrawList& list) {
                 return RenderWith(list, cpu::RasterRules{.fused_multiply_add = false});
               },
               {}});
  v.push_back({"lines snapped half to even, clipped at the guard band (Mesa 25)",
               true,
               8,
               false,
               [](const Scene&, const DrawList& list) {
                 return RenderWith(list, cpu::RasterRules{.lines_round_half_even = true, .wireframe_guard_band = true});
               },
               {}});
  v.push_back({"the edges clipping makes drawn too (Polygon Mode read strictly)",
               true,
               8,
               false,
               [](const Scene&, const DrawList& list) {
                 return RenderWith(list, cpu::RasterRules{.wireframe_clip_edges = true});
               },
               {}});
  return v;
}

std::vector<TwinVariant> DefectVariants() {
  std::vector<TwinVariant> v;
  v.push_back({"F transposed",
               false,
               8,
               false,
               [](const Scene&, DrawList list) {
                 for (DrawCall& d : list.draws) d.F = glm::transpose(d.F);
                 return DrawTwin(list);
               },
               {}});
  v.push_back({"y not flipped",
               false,
               8,
               false,
               [](const Scene&, const DrawList& list) { return FlippedRows(DrawTwin(list)); },
               {}});
  const auto unmoved = [](const DrawList& list) {
    return Rasterize(list, InWindow(list, [](glm::dvec2 p) { return p; }));
  };
  v.push_back({"sampling at pixel corners", false, 8, false,
               [](const Scene&, const DrawList& list) {
                 // Sampling at (x, y) instead of (x + 0.5, y + 0.5) is drawing the scene moved by half a pixel both
                 // ways.
                 return Rasterize(list, InWindow(list, [](glm::dvec2 p) { return p + glm::dvec2(0.5, 0.5); }));
               },
               unmoved});
  v.push_back({"every vertex shifted by half a pixel", false, 8, false,
               [](const Scene&, const DrawList& list) {
                 return Rasterize(list, InWindow(list, [](glm::dvec2 p) { return p + glm::dvec2(0.5, 0.0); }));
               },
               unmoved});
  v.push_back({"the depth test reversed",
               false,
               8,
               false,
               [](const Scene&, DrawList list) {
                 list.reversed_z = !list.reversed_z;
                 return DrawTwin(list);
               },
               {}});
  v.push_back({"one triangle dropped",
               false,
               8,
               false,
               [](const Scene&, DrawList list) {
                 // The first triangle of every mesh (so of every instance).
                 for (DrawMesh& mesh : list.meshes) {
                   if (mesh.triangles.empty()) continue;
                   mesh.triangles.erase(mesh.triangles.begin());
                   mesh.colours.erase(mesh.colours.begin());
                   if (!mesh.normals.empty()) mesh.normals.erase(mesh.normals.begin());
                 }
                 return DrawTwin(list);
               },
               {}});
  v.push_back({"front and back faces swapped",
               false,
               8,
               false,
               [](const Scene&, DrawList list) {
                 for (DrawMesh& mesh : list.meshes) {
                   for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
                   for (auto& n : mesh.normals) std::swap(n[1], n[2]);
                 }
                 return DrawTwin(list);
               },
               {}});
  v.push_back({"R and B swapped",
               false,
               8,
               false,
               [](const Scene&, const DrawList& list) {
                 Image image = DrawTwin(list);
                 for (std::size_t i = 0; i < image.rgba.size(); i += 4) std::swap(image.rgba[i], image.rgba[i + 2]);
                 return image;
               },
               {}});
  v.push_back({"the flat colour from the wrong vertex",
               false,
               8,
               false,
               [](const Scene&, const DrawList& list) {
                 // Lit flat triangles take their light at corner 1 instead of the provoking corner 0.
                 return DrawTwin(CornersRotated(list));
               },
               {}});
  v.push_back({"the near plane ignored", false, 8, false,
               [](const Scene&, const DrawList& list) {
                 // In front of the camera but nearer than the near plane: drawn at depth 0 instead of clipped.
                 cpu::ClipPositions clip = VertexStage(list);
                 for (auto& draw : clip) {
                   for (glm::vec4& c : draw) {
                     if (c.w > 0 && c.z < 0) c.z = 0;
                   }
                 }
                 return Rasterize(list, clip);
               },
               [](const DrawList& list) { return Rasterize(list, VertexStage(list)); }});
  v.push_back({"every drawn pixel grown to its right and lower neighbours (lines 2 px wide)",
               false,
               8,
               false,
               [](const Scene&, const DrawList& list) { return Grown(DrawTwin(list), list.background); },
               {}});
  v.push_back({"normals transformed by M_Model instead of N",
               false,
               8,
               false,
               [](const Scene&, DrawList list) {
                 if (list.lighting) {
                   for (LitInstance& i : list.lighting->instances) i.normal = glm::mat3(i.model);
                 }
                 return DrawTwin(list);
               },
               {}});
  return v;
}

}  // namespace twinraster::test
