#include "report/batch_page.hpp"

#include "image/thumbnail.hpp"
#include "report/markup.hpp"

#include <algorithm>
#include <sstream>

namespace twinraster::report {

namespace {

// Page order: the verdicts' own order puts failures first.
int Rank(Verdict verdict) { return static_cast<int>(verdict); }

// A link from the page's directory to a file, both made absolute first so that "-o out" and
// "--report out/report" meet.
std::string RelativeLink(const std::string& file, const std::filesystem::path& dir) {
  const std::filesystem::path target = std::filesystem::absolute(file).lexically_normal();
  const std::filesystem::path base = std::filesystem::absolute(dir).lexically_normal();
  return Href(target.lexically_relative(base).generic_string());
}

std::string Ms(double ms) { return Number(ms, ms < 10 ? 2 : 3); }

void Thumbnails(std::ostringstream& row, const RenderRecord& r, const std::filesystem::path& dir) {
  const ThumbnailSize size = ThumbnailSizeFor(r.width, r.height, kThumbnailSide);
  for (const char* kind : kThumbnailKinds) {
    const std::string full = FullImage(r, kind);
    if (full.empty()) {
      row << "<td class=\"none\">-</td>";
      continue;
    }
    row << "<td><a href=\"" << RelativeLink(full, dir) << "\"><img class=\"thumb\" loading=\"lazy\" src=\""
        << Href(ThumbnailPath(r, kind).generic_string()) << "\" width=\"" << size.width << "\" height=\"" << size.height
        << "\" alt=\"" << kind << " image of " << Escape(r.name) << "\"></a></td>";
  }
}

std::string DeviceText(const RenderRecord& r) {
  std::string text;
  if (const BackendRecord* gpu = r.Backend("gpu")) text = gpu->detail + (gpu->driver.empty() ? "" : " (" + gpu->driver + ")");
  if (r.twin) text += (text.empty() ? "" : "; ") + std::string("twin: ") + r.twin->text;
  else if (const BackendRecord* cpu = r.Backend("cpu")) text += (text.empty() ? "" : "; ") + cpu->detail;
  return text;
}

std::string TimesText(const RenderRecord& r) {
  std::string text = "load " + Ms(r.load_ms);
  for (const BackendRecord& b : r.backends) {
    if (b.Drawn()) text += ", " + b.name + " " + Ms(b.setup_ms + b.draw_ms + b.readback_ms);
  }
  if (r.verification) text += ", verify " + Ms(r.verify_ms);
  return text + ", total " + Ms(r.total_ms) + " ms";  // each backend: set-up, draw and readback
}

}  // namespace

BatchSummary Summarize(const std::vector<RenderRecord>& records, double total_ms) {
  BatchSummary s;
  s.scenes = records.size();
  s.total_ms = total_ms;
  for (const RenderRecord& r : records) {
    switch (VerdictOf(r)) {
      case Verdict::kError: ++s.errors; break;
      case Verdict::kCrashed: ++s.crashed; break;
      case Verdict::kDiffering: ++s.differing; break;
      case Verdict::kInconclusive: ++s.inconclusive; break;
      case Verdict::kVerified: ++s.verified; break;
      case Verdict::kIdentical: ++s.identical; break;
      case Verdict::kRendered: ++s.rendered; break;
    }
  }
  return s;
}

std::string FullImage(const RenderRecord& r, const std::string& kind) {
  if (kind == "diff") return r.diff;
  if (kind == "map") return r.map;
  const BackendRecord* b = r.Backend(kind);
  return b && b->Drawn() && b->output != "-" ? b->output : "";
}

std::filesystem::path ThumbnailPath(const RenderRecord& r, const std::string& kind) {
  return std::filesystem::path("thumbs") / (r.name + "-" + kind + ".png");
}

std::vector<const RenderRecord*> PageOrder(const std::vector<RenderRecord>& records) {
  std::vector<const RenderRecord*> order;
  for (const RenderRecord& r : records) order.push_back(&r);
  std::stable_sort(order.begin(), order.end(),
                   [](const RenderRecord* a, const RenderRecord* b) { return Rank(VerdictOf(*a)) < Rank(VerdictOf(*b)); });
  return order;
}

std::string BatchPageHtml(const std::vector<RenderRecord>& records, const std::filesystem::path& dir, double total_ms) {
  const BatchSummary s = Summarize(records, total_ms);
  std::ostringstream page;
  page << PageStart("twinraster render: " + std::to_string(s.scenes) + " scenes") << "<h1>twinraster render</h1>\n";
  page << "<table class=\"summary\" id=\"summary\"><tr>";
  const std::pair<const char*, std::size_t> counts[] = {{"scenes", s.scenes},       {"identical", s.identical},
                                                        {"verified", s.verified},   {"inconclusive", s.inconclusive},
                                                        {"differing", s.differing},
                                                        {"crashed", s.crashed},     {"errors", s.errors},
                                                        {"drawn only", s.rendered}};
  for (const auto& [name, count] : counts) page << "<th class=\"n\">" << name << "</th>";
  page << "<th class=\"n\">total time</th></tr>\n<tr>";
  for (const auto& [name, count] : counts) page << "<td class=\"n\" data-count=\"" << name << "\">" << count << "</td>";
  page << "<td class=\"n\" data-count=\"seconds\">" << Number(total_ms / 1000, 4) << " s</td></tr></table>\n";
  page << "<p>identical: the GPU's and the twin's images agree bit for bit. verified: they differ (or one image "
          "was judged) and every pixel is one Vulkan allows. inconclusive: no pixel is wrong, but too few are certain "
          "to tell a broken image (docs/verify.md). differing: a pixel the verifier rejects, or a difference "
          "where the twin copies this driver exactly. Thumbnails link to the full PNGs.</p>\n";
  page << "<table id=\"scenes\">\n<thead><tr><th>scene</th><th>GPU</th><th>twin</th><th>difference</th><th>verification "
          "map</th><th>verdict</th><th class=\"n\">differing px</th><th class=\"n\">violating px</th><th>device, rules "
          "and times</th></tr></thead>\n<tbody>\n";
  for (const RenderRecord* r : PageOrder(records)) {
    const Verdict verdict = VerdictOf(*r);
    std::ostringstream row;
    row << "<tr class=\"scene\" data-verdict=\"" << VerdictName(verdict) << "\" data-scene=\"" << Escape(r->scene)
        << "\"><td class=\"name\"><b>" << Escape(r->name) << "</b><br><span class=\"path\">" << Escape(r->scene)
        << "</span></td>";
    if (verdict == Verdict::kError) {
      row << "<td colspan=\"4\" class=\"none\">no images</td>";
    } else {
      Thumbnails(row, *r, dir);
    }
    row << "<td class=\"reason verdict-" << VerdictName(verdict) << "\"><b>" << VerdictName(verdict) << "</b><br>"
        << Escape(VerdictReason(*r)) << "</td>";
    row << "<td class=\"n differing\">" << (r->comparison ? std::to_string(r->comparison->differing_pixels) : "-") << "</td>";
    row << "<td class=\"n violations\">" << (r->verification ? std::to_string(r->verification->violations) : "-") << "</td>";
    row << "<td class=\"details\">" << Escape(DeviceText(*r)) << "<br>" << (verdict == Verdict::kError ? "" : TimesText(*r))
        << "</td></tr>\n";
    page << row.str();
  }
  page << "</tbody></table>\n" << kPageEnd;
  return page.str();
}

}  // namespace twinraster::report
