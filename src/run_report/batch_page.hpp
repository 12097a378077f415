// `render --report DIR`: one page for a batch of scenes, failures first, each row the scene's
// images as thumbnails (linked to the full PNGs), its verdict, counts, device, rules and times.
// Self-contained: inline CSS, no script, PNGs beside it; it reads the batch's result (its records,
// counts and time) and nothing else.
#pragma once

#include "run/batch_result.hpp"
#include "run/run_record.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace twinraster::run_report {

// The longer side of a thumbnail, in pixels.
inline constexpr std::uint32_t kThumbnailSide = 96;

// The images a row shows, in order.
enum class ImageKind { kGpu, kCpu, kDiff, kMap };
inline constexpr ImageKind kThumbnailKinds[] = {ImageKind::kGpu, ImageKind::kCpu, ImageKind::kDiff, ImageKind::kMap};
const char* ImageKindName(ImageKind kind);  // "gpu", "cpu", "diff", "map"
// The record's file of `kind` ("" when there is none).
std::string FullImage(const run::RunRecord& record, ImageKind kind);
// Where the thumbnail of `kind` goes, relative to the report's directory.
std::filesystem::path ThumbnailPath(const run::RunRecord& record, ImageKind kind);

// The records in the page's order: failures first (errors, crashes, differing), then verified,
// identical and drawn; the batch's order within each.
std::vector<const run::RunRecord*> PageOrder(const std::vector<run::RunRecord>& records);

// The page, for `dir`/index.html: links to images are relative to `dir`.
std::string BatchPageHtml(const run::BatchResult& batch, const std::filesystem::path& dir);

}  // namespace twinraster::run_report
