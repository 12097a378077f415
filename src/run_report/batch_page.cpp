#include "run_report/batch_page.hpp"

#include "base/counted.hpp"
#include "image/thumbnail.hpp"
#include "markup/markup.hpp"
#include "run_report/render_outputs.hpp"

#include <algorithm>
#include <sstream>

namespace twinraster::run_report {

namespace {

// Page order: the verdicts' own order puts failures first.
int Rank(run::Verdict verdict) { return static_cast<int>(verdict); }

// A link from the page's directory to a file, both made absolute first so that "-o out" and
// "--report out/report" meet.
std::string RelativeLink(const std::string& file, const std::filesystem::path& dir) {
  const std::filesystem::path target = std::filesystem::absolute(file).lexically_normal();
  const std::filesystem::path base = std::filesystem::absolute(dir).lexically_normal();
  return markup::Href(target.lexically_relative(base).generic_string());
}

std::string Ms(double ms) { return markup::Number(ms, ms < 10 ? 2 : 3); }

void Thumbnails(std::ostringstream& row, const run::RunRecord& r, const std::filesystem::path& dir) {
  const ThumbnailSize size = ThumbnailSizeFor(r.width, r.height, kThumbnailSide);
  for (ImageKind kind : kThumbnailKinds) {
    const std::string full = FullImage(r, kind);
    if (full.empty()) {
      row << "<td class=\"none\">-</td>";
      continue;
    }
    row << "<td><a href=\"" << RelativeLink(full, dir) << "\"><img class=\"thumb\" loading=\"lazy\" src=\""
        << markup::Href(ThumbnailPath(r, kind).generic_string()) << "\" width=\"" << size.width << "\" height=\""
        << size.height << "\" alt=\"" << ImageKindName(kind) << " image of " << markup::Escape(r.name)
        << "\"></a></td>";
  }
}

std::string DeviceText(const run::RunRecord& r) {
  std::string text;
  if (const run::BackendRecord* gpu = r.Find(run::Backend::kGpu))
    text = gpu->detail + (gpu->driver.empty() ? "" : " (" + gpu->driver + ")");
  if (r.twin)
    text += (text.empty() ? "" : "; ") + std::string("twin: ") + r.twin->text;
  else if (const run::BackendRecord* cpu = r.Find(run::Backend::kCpu))
    text += (text.empty() ? "" : "; ") + cpu->detail;
  return text;
}

std::string TimesText(const run::RunRecord& r) {
  std::string text = "load " + Ms(r.load_ms);
  for (const run::BackendRecord& b : r.backends) {
    if (b.Drawn()) text += ", " + std::string(b.Name()) + " " + Ms(b.setup_ms + b.draw_ms + b.readback_ms);
  }
  if (r.verification) text += ", verify " + Ms(r.verify_ms);
  return text + ", total " + Ms(r.total_ms) + " ms";  // each backend: set-up, draw and readback
}

}  // namespace

const char* ImageKindName(ImageKind kind) {
  switch (kind) {
    case ImageKind::kGpu: return "gpu";
    case ImageKind::kCpu: return "cpu";
    case ImageKind::kDiff: return "diff";
    case ImageKind::kMap: return "map";
  }
  return "?";
}

std::string FullImage(const run::RunRecord& r, ImageKind kind) {
  if (kind == ImageKind::kDiff) return r.diff;
  if (kind == ImageKind::kMap) return r.map;
  const run::BackendRecord* b = r.Find(kind == ImageKind::kGpu ? run::Backend::kGpu : run::Backend::kCpu);
  return b && b->Drawn() && b->output != "-" ? b->output : "";
}

std::filesystem::path ThumbnailPath(const run::RunRecord& r, ImageKind kind) {
  return std::filesystem::path("thumbs") / (r.name + "-" + ImageKindName(kind) + ".png");
}

std::vector<const run::RunRecord*> PageOrder(const std::vector<run::RunRecord>& records) {
  std::vector<const run::RunRecord*> order;
  for (const run::RunRecord& r : records) order.push_back(&r);
  std::stable_sort(order.begin(), order.end(), [](const run::RunRecord* a, const run::RunRecord* b) {
    return Rank(a->verdict) < Rank(b->verdict);
  });
  return order;
}

std::string BatchPageHtml(const run::BatchResult& batch, const std::filesystem::path& dir) {
  using run::Verdict;
  std::ostringstream page;
  page << markup::PageStart("twinraster render: " + Counted(batch.Scenes(), "scene")) << "<h1>twinraster render</h1>\n";
  page << "<table class=\"summary\" id=\"summary\"><tr>";
  const std::pair<const char*, std::size_t> counts[] = {{"scenes", batch.Scenes()},
                                                        {"identical", batch.Count(Verdict::kIdentical)},
                                                        {"verified", batch.Count(Verdict::kVerified)},
                                                        {"inconclusive", batch.Count(Verdict::kInconclusive)},
                                                        {"differing", batch.Count(Verdict::kDiffering)},
                                                        {"crashed", batch.Count(Verdict::kCrashed)},
                                                        {"errors", batch.Count(Verdict::kError)},
                                                        {"drawn only", batch.Count(Verdict::kRendered)}};
  for (const auto& [name, count] : counts) page << "<th class=\"n\">" << name << "</th>";
  page << "<th class=\"n\">total time</th></tr>\n<tr>";
  for (const auto& [name, count] : counts) page << "<td class=\"n\" data-count=\"" << name << "\">" << count << "</td>";
  page << "<td class=\"n\" data-count=\"seconds\">" << markup::Number(batch.total_ms / 1000, 4)
       << " s</td></tr></table>\n";
  page << "<p>identical: the GPU's and the twin's images agree bit for bit. verified: they differ (or one image "
          "was judged) and every pixel is one Vulkan allows. inconclusive: no pixel is wrong, but too few are certain "
          "to tell a broken image (docs/verify.md). differing: a pixel the verifier rejects, or a difference "
          "where the twin copies this driver exactly. Thumbnails link to the full PNGs.</p>\n";
  page
      << "<table id=\"scenes\">\n<thead><tr><th>scene</th><th>GPU</th><th>twin</th><th>difference</th><th>verification "
         "map</th><th>verdict</th><th class=\"n\">differing px</th><th class=\"n\">violating px</th><th>device, rules "
         "and times</th></tr></thead>\n<tbody>\n";
  for (const run::RunRecord* r : PageOrder(batch.Records())) {
    const run::Verdict verdict = r->verdict;
    std::ostringstream row;
    row << "<tr class=\"scene\" data-verdict=\"" << run::VerdictName(verdict) << "\" data-scene=\""
        << markup::Escape(r->scene) << "\"><td class=\"name\"><b>" << markup::Escape(r->name)
        << "</b><br><span class=\"path\">" << markup::Escape(r->scene) << "</span></td>";
    if (verdict == run::Verdict::kError) {
      row << "<td colspan=\"4\" class=\"none\">no images</td>";
    } else {
      Thumbnails(row, *r, dir);
    }
    row << "<td class=\"reason verdict-" << run::VerdictName(verdict) << "\"><b>" << run::VerdictName(verdict)
        << "</b><br>" << markup::Escape(VerdictReason(*r)) << "</td>";
    row << "<td class=\"n differing\">" << (r->comparison ? std::to_string(r->comparison->differing_pixels) : "-")
        << "</td>";
    row << "<td class=\"n violations\">" << (r->verification ? std::to_string(r->verification->violations) : "-")
        << "</td>";
    row << "<td class=\"details\">" << markup::Escape(DeviceText(*r)) << "<br>"
        << (verdict == run::Verdict::kError ? "" : TimesText(*r)) << "</td></tr>\n";
    page << row.str();
  }
  page << "</tbody></table>\n" << markup::kPageEnd;
  return page.str();
}

}  // namespace twinraster::run_report
