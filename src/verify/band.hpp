// One band of the frame's rows as the verifier's two passes leave it: its own primitives, its judge
// and the draws that reach it; and what is gathered from the bands once they are done (their counts
// merged, the colours allowed at the pixels the report names). It does not run the passes
// (verifier.cpp does), nor judge a pixel (pixel_judge.hpp does).
#pragma once

#include "chain/draw_list.hpp"
#include "image/image.hpp"
#include "verify/frame_shared.hpp"
#include "verify/pixel_judge.hpp"
#include "verify/primitives.hpp"
#include "verify/sole_surfaces.hpp"
#include "verify/verification.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace twinraster::verify {

// A band of rows [row0, row1): each band sees every primitive and judges its own pixels.
struct Band {
  Band(const FrameShared& frame, const DrawList& draws, const Image& image, const VerifyOptions& options, int row0,
       int row1)
      : list(draws),
        shared(frame),
        primitives(frame, draws, options),
        judge(image, draws.background, draws.reversed_z, row0, row1),
        sole(judge),
        fast(options.fast_paths) {}
  const DrawList& list;
  const FrameShared& shared;
  Primitives primitives;
  FrameJudge judge;
  SoleSurfaces sole;  // pass 2's tiles one surface settles (a fast path)
  std::uint64_t shapes_offered = 0;
  std::vector<DrawReach> reaching;  // pass 1 fills it, pass 2 and AllowedAt read it
  Verification counts;
  bool fast = true;
};

// The rows of each band for a frame `rows` high: whole 16-row tiles, one band per hardware thread.
int BandRows(int rows);

// Pass 2 at one pixel of the band only, gathering what each surface that may show there allows:
// only draws whose boxes in the band hold the pixel can.
std::vector<ColourRange> AllowedAt(const Band& band, int x, int y);

// The bands' counts summed into `result`; the first violation is the first band's, the worst the
// first of the largest distance. The colours allowed are gathered for those two pixels only.
void MergeBands(const std::vector<std::unique_ptr<Band>>& bands, Verification& result);

}  // namespace twinraster::verify
