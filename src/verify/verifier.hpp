// The verifier: judges any image of a scene (from any GPU, engine or file) by what a conformant
// Vulkan implementation may draw, pixel by pixel, beside the bit-exact twin.
#pragma once

#include "chain/draw_list.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"
#include "verify/verification.hpp"

namespace twinraster::verify {

// `list` must be BuildDrawList(scene) (its float F are what the image was drawn from); the truth's
// chain is recomputed from `scene` in double, one instance at a time. Throws std::invalid_argument
// when the image's size is not the canvas's, or the list does not belong to the scene.
Verification VerifyImage(const Scene& scene, const DrawList& list, const Image& image,
                         const VerifyOptions& options = {});

}  // namespace twinraster::verify
