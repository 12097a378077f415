// Variants of the CPU twin for testing the verifier (test code, not the product): conformant
// rasterizers that differ from lavapipe, and twins with a real bug. Each draws a scene's image.
#pragma once

#include "chain/draw_list.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"

#include <functional>
#include <string>
#include <vector>

namespace twinraster::test {

struct TwinVariant {
  std::string name;
  bool conformant = false;   // a conformant implementation may draw this image
  int subpixel_bits = 8;     // what the variant snaps to, for the verifier
  bool filled_only = false;  // it draws no wireframes
  std::function<Image(const Scene&, const DrawList&)> draw;
  // A defect's image without the defect, drawn the same way (the same vertex stage): what the bug
  // changes. Empty: the twin's own image.
  std::function<Image(const DrawList&)> baseline;
};

// The conformant ones: 4 subpixel bits, the bottom-right tie rule, everything in double (the
// truth's rasterizer on the list's positions), no FMA, Mesa 25's lines (guard-band clipping), the
// edges clipping makes drawn too. The twin itself is the one that leaves those edges out.
std::vector<TwinVariant> ConformantVariants();

// The defects: F transposed, y not flipped, sampling at pixel corners, every vertex shifted half a
// pixel, the depth test reversed, one triangle dropped, front and back faces swapped, R and B
// swapped, the flat colour from the wrong vertex, the near plane ignored, every drawn pixel grown
// by one (lines 2 px wide), normals by M_Model.
std::vector<TwinVariant> DefectVariants();

// The twin itself, with Mesa 22.3.6's rules on AVX2 (lavapipe's image on this machine).
Image DrawTwin(const DrawList& list);

}  // namespace twinraster::test
