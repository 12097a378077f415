// `verify`'s run: one image of a scene, drawn anywhere, judged by the rules of the device that drew
// it, with the verdict render would give it. It reads no file (cli/ hands it the scene, the image
// and the rules from the image's notes or the options) and writes nothing.
#pragma once

#include "chain/draw_list.hpp"
#include "image/image.hpp"
#include "run/verdict.hpp"
#include "scene/scene.hpp"
#include "verify/verification.hpp"

#include <cstdint>
#include <optional>

namespace twinraster::run {

struct ImageJudgement {
  verify::Verification verification;
  double verify_ms = 0;
  std::optional<Image> map;              // when asked for
  Verdict verdict = Verdict::kVerified;  // kVerified, kInconclusive or kDiffering
  std::uint64_t not_opaque = 0;          // pixels whose alpha is not 255: alpha is not judged
};

ImageJudgement JudgeImage(const Scene& scene, const Image& image, const verify::VerifyOptions& rules, bool map);
// The same, for a caller that already has the scene's draw list (a run, the bench).
ImageJudgement JudgeImage(const Scene& scene, const DrawList& list, const Image& image,
                          const verify::VerifyOptions& rules, bool map);

}  // namespace twinraster::run
