// The report layer on its own: escaping, links, verdicts and their order, the JUnit counts, counts
// in words, plots on log axes, and thumbnails that keep a single marked pixel.
#include "base/counted.hpp"
#include "image/thumbnail.hpp"
#include "report/batch_page.hpp"
#include "report/junit.hpp"
#include "report/markup.hpp"
#include "report/render_outputs.hpp"
#include "report/svg_plot.hpp"
#include "support/catch.hpp"

#include <nlohmann/json.hpp>

#include <string>

using namespace twinraster;
using namespace twinraster::report;

namespace {

// The record with its verdict decided, as a run leaves it.
run::RunRecord Decided(run::RunRecord r) {
  r.verdict = run::VerdictOf(r);
  return r;
}

run::RunRecord Drawn(const std::string& name, std::uint64_t differing, std::optional<bool> verified) {
  run::RunRecord r;
  r.scene = "scenes/" + name + ".json", r.name = name, r.width = 64, r.height = 48;
  run::BackendRecord gpu, cpu;
  gpu.backend = run::Backend::kGpu, gpu.output = "out/" + name + "-gpu.png";
  cpu.backend = run::Backend::kCpu, cpu.output = "out/" + name + "-cpu.png";
  r.backends = {gpu, cpu};
  r.comparison = Comparison{true, differing, differing ? 3 : 0};
  if (verified) {
    r.verification = verify::Verification{};
    r.verification->violations = *verified ? 0 : 2;
    r.verification->covered = 50, r.verification->certain = 3000, r.verification->background_excluded = 40;
    if (!*verified) r.verification->first = r.verification->worst = verify::Violation{1, 2, {}, 9, {}};
    r.judged = run::Backend::kGpu;
  }
  return Decided(r);
}

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("Escape: markup, quotes, ampersands and control characters come out as text", "[report]") {
  CHECK(Escape("<script>alert(\"x\")</script>") == "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt;");
  CHECK(Escape("a&b 'c'") == "a&amp;b &#39;c&#39;");
  CHECK(Escape("tab\there\x01") == "tab\there\xEF\xBF\xBD");
  CHECK(Escape("plain") == "plain");
}

TEST_CASE("Href: file names become links that point at themselves", "[report]") {
  CHECK(Href("../out/a b#1.png") == "../out/a%20b%231.png");
  CHECK(Href("thumbs/<x>\".png") == "thumbs/%3Cx%3E%22.png");
  CHECK(Href("x-y_z.~1/2.png") == "x-y_z.~1/2.png");
}

TEST_CASE("Verdicts: errors, crashes and violations fail, and failures sort first with the batch's order kept within",
          "[report]") {
  const run::RunRecord error = run::ErrorRecord("broken.json", "broken.json: line 1, column 2: bad");
  run::RunRecord crashed = Drawn("crashed", 0, std::nullopt);
  crashed.backends[0].status = run::BackendStatus::kCrashed,
  crashed.backends[0].problem = "SIGSEGV in the Vulkan driver";
  crashed.comparison.reset();
  run::RunRecord promised = Drawn("promised", 5, true);
  promised.twin = twin_rules::TwinRules{};
  promised.twin->exact = true;
  const std::vector<run::RunRecord> records = {
      Drawn("same", 0, std::nullopt),  Drawn("allowed", 7, true), Drawn("wrong", 7, false), error, Decided(crashed),
      Drawn("same2", 0, std::nullopt), Decided(promised)};
  CHECK(records[0].verdict == run::Verdict::kIdentical);
  CHECK(records[1].verdict == run::Verdict::kVerified);
  CHECK(records[2].verdict == run::Verdict::kDiffering);
  CHECK(records[3].verdict == run::Verdict::kError);
  CHECK(records[4].verdict == run::Verdict::kCrashed);
  CHECK(records[6].verdict == run::Verdict::kDiffering);  // the twin promised identical images
  CHECK(VerdictReason(records[3]) == "broken.json: line 1, column 2: bad");
  CHECK(VerdictReason(records[4]) == "gpu crashed: SIGSEGV in the Vulkan driver");

  std::vector<std::string> order;
  for (const run::RunRecord* r : PageOrder(records)) order.push_back(r->name);
  CHECK(order == std::vector<std::string>{"broken", "crashed", "wrong", "promised", "allowed", "same", "same2"});

  const BatchSummary s = Summarize(records, 1500);
  CHECK(s.scenes == 7);
  CHECK(s.errors == 1);
  CHECK(s.crashed == 1);
  CHECK(s.differing == 2);
  CHECK(s.verified == 1);
  CHECK(s.identical == 2);

  const std::string xml = JUnitXml(records, 1500, false);
  CHECK(Count(xml, "<testcase ") == 7);
  CHECK(Count(xml, "<failure ") == 2);
  CHECK(Count(xml, "<error ") == 2);
  CHECK(xml.find("tests=\"7\" failures=\"2\" errors=\"2\"") != std::string::npos);
  CHECK(xml.find("time=\"1.500000\"") != std::string::npos);
}

TEST_CASE("Batch page: a row per scene, links relative to the page, thumbnails only where an image exists",
          "[report]") {
  const std::vector<run::RunRecord> records = {Drawn("same", 0, std::nullopt), Drawn("allowed", 7, true)};
  std::vector<run::RunRecord> with_diff = records;
  with_diff[1].diff = "out/allowed-diff.png";
  const std::string page = BatchPageHtml(with_diff, "report", 2000);
  CHECK(Count(page, "<tr class=\"scene\"") == 2);
  CHECK(page.find("href=\"../out/same-gpu.png\"") != std::string::npos);
  CHECK(page.find("src=\"thumbs/allowed-diff.png\"") != std::string::npos);
  CHECK(page.find("src=\"thumbs/same-diff.png\"") == std::string::npos);
  CHECK(page.find("loading=\"lazy\"") != std::string::npos);
  CHECK(page.find("<script") == std::string::npos);
}

TEST_CASE("The record's JSON and text: render --json's numbers come from it", "[report]") {
  const run::RunRecord r = Drawn("allowed", 7, true);
  const nlohmann::ordered_json j = RenderJson(r);
  CHECK(j.at("differing_pixels") == 7);
  CHECK(j.at("verify").at("pixels").at("violations") == 0);
  CHECK(j.at("backends").at("gpu").at("output") == "out/allowed-gpu.png");
  const std::string text = RenderText(r, false);
  CHECK(text.find("gpu vs cpu: 64 x 48: 7 differing pixels") != std::string::npos);
  CHECK(text.find("verdict: the images differ in 7 px, all within what Vulkan allows") != std::string::npos);
}

TEST_CASE("Counts agree with their nouns: 1 instance, 1 triangle, 1 differing pixel, and 2 of each in the plural",
          "[report]") {
  run::RunRecord one = Drawn("one", 1, true);
  one.instances = 1, one.triangles = 1;
  const std::string text = RenderText(one, false);
  CHECK_THAT(text, HasSubstring("scenes/one.json: 1 instance, 1 triangle, 64 x 48"));
  CHECK_THAT(text, HasSubstring("gpu vs cpu: 64 x 48: 1 differing pixel, max channel difference 3"));
  run::RunRecord two = Drawn("two", 2, true);
  two.instances = 2, two.triangles = 2;
  CHECK_THAT(RenderText(two, false), HasSubstring("scenes/two.json: 2 instances, 2 triangles, 64 x 48"));
  CHECK_THAT(RenderText(two, false), HasSubstring("64 x 48: 2 differing pixels,"));
  CHECK(Counted(1, "vertex", "vertices") == "1 vertex");
  CHECK(Counted(0u, "vertex", "vertices") == "0 vertices");
  CHECK(Counted(std::size_t{3}, "copy", "copies") == "3 copies");
  CHECK(ValidIndices(1) == ": give 0");
  CHECK(ValidIndices(5) == ": give 0 to 4");
  CHECK(ValidIndices(0).empty());
}

TEST_CASE("PlotSvg: each point carries its numbers, and on a log axis 0 sits on the floor", "[report]") {
  Plot plot;
  plot.x = {"ms", true, std::nullopt};
  plot.y = {"error", true, 1e-9};
  plot.series = {{"<a&b>", "#123456", {{10, 0, "zero"}, {100, 1e-3, "some"}}, true}};
  const std::string svg = PlotSvg(plot);
  CHECK(Count(svg, "class=\"point\"") == 2);
  CHECK(svg.find("data-x=\"10\" data-y=\"0\"") != std::string::npos);
  CHECK(svg.find("data-x=\"100\" data-y=\"0.001\"") != std::string::npos);
  CHECK(svg.find("≤1e-9") != std::string::npos);
  CHECK(svg.find("&lt;a&amp;b&gt;") != std::string::npos);
  CHECK(svg.find("<a&b>") == std::string::npos);
  CHECK(svg.find("nan") == std::string::npos);
}

TEST_CASE("PlotSvg: a linear axis ticks round numbers and starts at 0 for positive data", "[report]") {
  Plot plot;
  plot.x = {"instances", false, std::nullopt};
  plot.y = {"ms", false, std::nullopt};
  plot.series = {{"twin", "#000", {{1, 2, "one"}, {9, 40, "nine"}}, true}};
  const std::string svg = PlotSvg(plot);
  CHECK(svg.find(">0</text>") != std::string::npos);
  CHECK(svg.find(">10</text>") != std::string::npos);
  CHECK(svg.find("(log)") == std::string::npos);
  CHECK(svg.find("<polyline") != std::string::npos);
}

TEST_CASE("Thumbnail: pictures are averaged, one marked pixel of a diff survives", "[report]") {
  Image diff(600, 400);
  for (std::size_t i = 0; i < diff.rgba.size(); i += 4)
    diff.rgba[i] = diff.rgba[i + 1] = diff.rgba[i + 2] = 220, diff.rgba[i + 3] = 255;
  std::uint8_t* marked = diff.pixel(301, 117);
  marked[0] = 255, marked[1] = 0, marked[2] = 0;
  const Image mean = Thumbnail(diff, 96), kept = Thumbnail(diff, 96, ThumbnailFilter::kMostSaturated);
  REQUIRE(mean.width == 96);
  REQUIRE(mean.height == 64);
  CHECK(ThumbnailSizeFor(600, 400, 96).width == 96);
  CHECK(ThumbnailSizeFor(600, 400, 96).height == 64);
  std::size_t red_mean = 0, red_kept = 0;
  for (std::size_t i = 0; i < mean.rgba.size(); i += 4) {
    red_mean += mean.rgba[i] == 255 && mean.rgba[i + 1] == 0;
    red_kept += kept.rgba[i] == 255 && kept.rgba[i + 1] == 0;
  }
  CHECK(red_mean == 0);
  CHECK(red_kept == 1);
  const Image small(50, 20);
  CHECK(Thumbnail(small, 96).width == 50);
}
