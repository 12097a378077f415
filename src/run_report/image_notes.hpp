// The notes render writes into each PNG it draws, and verify reads back: which device drew the
// image and how it rasterizes (subPixelPrecisionBits, strictLines), so that judging the image later
// uses what that device reported. It does not vouch for them: a file's notes are what it says.
#pragma once

#include "files/png_file.hpp"
#include "verify/drawn_by.hpp"

#include <optional>
#include <string>

namespace twinraster::run_report {

files::PngNotes NotesOf(const verify::DrawnBy& drawn_by);
// Empty when the notes lack a device or a rule, or hold one out of range (bits outside 0..24).
std::optional<verify::DrawnBy> DrawnByOf(const files::PngNotes& notes);

}  // namespace twinraster::run_report
