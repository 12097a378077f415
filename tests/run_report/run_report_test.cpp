// A run's outputs on their own: verdicts and their order, the batch page, the JUnit counts, the
// record's JSON and text, and counts in words.
#include "base/counted.hpp"
#include "run_report/batch_page.hpp"
#include "run_report/junit.hpp"
#include "run_report/render_outputs.hpp"
#include "support/catch.hpp"

#include <nlohmann/json.hpp>

#include <string>

using namespace twinraster;
using namespace twinraster::run_report;

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

  run::BatchResult batch;
  for (const run::RunRecord& r : records) batch.Add(r);
  batch.total_ms = 1500;
  const std::string xml = JUnitXml(batch, false);
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
  run::BatchResult batch;
  for (const run::RunRecord& r : with_diff) batch.Add(r);
  batch.total_ms = 2000;
  const std::string page = BatchPageHtml(batch, "report");
  CHECK(Count(page, "<tr class=\"scene\"") == 2);
  CHECK(page.find("href=\"../out/same-gpu.png\"") != std::string::npos);
  CHECK(page.find("src=\"thumbs/allowed-diff.png\"") != std::string::npos);
  CHECK(page.find("src=\"thumbs/same-diff.png\"") == std::string::npos);
  CHECK(page.find("loading=\"lazy\"") != std::string::npos);
  CHECK(page.find("<script") == std::string::npos);
  // The summary's counts are the batch's.
  CHECK(page.find("data-count=\"scenes\">2<") != std::string::npos);
  CHECK(page.find("data-count=\"identical\">1<") != std::string::npos);
  CHECK(page.find("data-count=\"verified\">1<") != std::string::npos);
  CHECK(page.find("data-count=\"seconds\">2 s<") != std::string::npos);
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
