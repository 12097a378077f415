#include "run_report/junit.hpp"

#include "markup/markup.hpp"
#include "run_report/render_outputs.hpp"

#include <cstdio>
#include <sstream>

namespace twinraster::run_report {

namespace {

// Seconds as xs:decimal, which has no exponent: "0.000012", never "1.2e-05".
std::string Seconds(double ms) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6f", ms / 1000);
  return text;
}

}  // namespace

std::string JUnitXml(const run::BatchResult& batch, bool verify_asked) {
  using run::Verdict;
  const std::size_t failures = batch.Count(Verdict::kDiffering);
  const std::size_t errors = batch.Count(Verdict::kError) + batch.Count(Verdict::kCrashed);
  const std::size_t skipped = batch.Count(Verdict::kInconclusive);
  const std::string counts = "tests=\"" + std::to_string(batch.Scenes()) + "\" failures=\"" + std::to_string(failures) +
                             "\" errors=\"" + std::to_string(errors) + "\" skipped=\"" + std::to_string(skipped) + "\"";
  const std::string seconds = Seconds(batch.total_ms);
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"twinraster render\" " << counts << " time=\""
      << seconds << "\">\n<testsuite name=\"twinraster render\" " << counts << " time=\"" << seconds << "\">\n";
  for (const run::RunRecord& r : batch.Records()) {
    const run::Verdict v = r.verdict;
    xml << "<testcase classname=\"twinraster.render\" name=\"" << markup::Escape(r.scene) << "\" time=\""
        << Seconds(r.total_ms) << "\">\n";
    if (run::IsFailure(v)) {
      const char* element = v == run::Verdict::kDiffering ? "failure" : "error";
      xml << "<" << element << " type=\"" << run::VerdictName(v) << "\" message=\"" << markup::Escape(VerdictReason(r))
          << "\"/>\n";
    }
    // Neither passed nor failed: JUnit's nearest word for a test that could not decide.
    if (run::IsInconclusive(v)) xml << "<skipped message=\"" << markup::Escape(VerdictReason(r)) << "\"/>\n";
    xml << "<system-out>" << markup::Escape(v == run::Verdict::kError ? r.error + "\n" : RenderText(r, verify_asked))
        << "</system-out>\n";
    xml << "</testcase>\n";
  }
  xml << "</testsuite>\n</testsuites>\n";
  return xml.str();
}

}  // namespace twinraster::run_report
