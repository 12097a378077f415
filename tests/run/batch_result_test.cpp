// A batch's one result: its counts per verdict, its worst verdict ranked on the verdicts, and the
// exit code that gives, checked against the rule batches have always exited by (the worst of the
// scenes' exit codes, inconclusive milder than any problem).
#include "run/batch_result.hpp"

#include "support/catch.hpp"

#include <vector>

using namespace twinraster;
using run::Verdict;

namespace {

constexpr Verdict kAll[] = {Verdict::kError,    Verdict::kCrashed,   Verdict::kDiffering, Verdict::kInconclusive,
                            Verdict::kVerified, Verdict::kIdentical, Verdict::kRendered};

run::RunRecord WithVerdict(Verdict verdict, const std::string& scene) {
  run::RunRecord r;
  r.scene = scene;
  r.verdict = verdict;
  return r;
}

// The batch's exit code as render ranked exit codes before verdicts were ranked: 0, then 6, then
// 1 to 5 in their order; kept here as the outcome the ranking must give.
int ExitCodeRankedOnCodes(const std::vector<Verdict>& verdicts) {
  const auto rank = [](int code) { return code == 6 ? 1 : code == 0 ? 0 : code + 1; };
  int worst = 0;
  for (Verdict v : verdicts) {
    if (rank(run::ExitCodeOf(v)) > rank(worst)) worst = run::ExitCodeOf(v);
  }
  return worst;
}

run::BatchResult BatchOf(const std::vector<Verdict>& verdicts) {
  run::BatchResult batch;
  for (std::size_t i = 0; i < verdicts.size(); ++i) batch.Add(WithVerdict(verdicts[i], "s" + std::to_string(i)));
  return batch;
}

}  // namespace

TEST_CASE("Severity ranks success below inconclusive and inconclusive below differing and error and crashed", "[run]") {
  CHECK(run::Severity(Verdict::kIdentical) < run::Severity(Verdict::kVerified));
  CHECK(run::Severity(Verdict::kVerified) < run::Severity(Verdict::kRendered));
  CHECK(run::Severity(Verdict::kRendered) < run::Severity(Verdict::kInconclusive));
  CHECK(run::Severity(Verdict::kInconclusive) < run::Severity(Verdict::kDiffering));
  CHECK(run::Severity(Verdict::kDiffering) < run::Severity(Verdict::kError));
  CHECK(run::Severity(Verdict::kError) < run::Severity(Verdict::kCrashed));
  CHECK(run::Worse(Verdict::kCrashed, Verdict::kError) == Verdict::kCrashed);
  CHECK(run::Worse(Verdict::kError, Verdict::kCrashed) == Verdict::kCrashed);
  CHECK(run::Worse(Verdict::kInconclusive, Verdict::kRendered) == Verdict::kInconclusive);
  CHECK(run::Worse(Verdict::kVerified, Verdict::kVerified) == Verdict::kVerified);
}

TEST_CASE("The worst verdict gives the exit code batches exited with before: every pair and triple of verdicts",
          "[run]") {
  for (Verdict a : kAll) {
    for (Verdict b : kAll) {
      CAPTURE(run::VerdictName(a), run::VerdictName(b));
      CHECK(BatchOf({a, b}).ExitCode() == ExitCodeRankedOnCodes({a, b}));
      for (Verdict c : kAll) {
        CAPTURE(run::VerdictName(c));
        CHECK(BatchOf({a, b, c}).ExitCode() == ExitCodeRankedOnCodes({a, b, c}));
      }
    }
  }
  CHECK(BatchOf({Verdict::kIdentical, Verdict::kInconclusive, Verdict::kVerified}).ExitCode() == 6);
  CHECK(BatchOf({Verdict::kInconclusive, Verdict::kDiffering}).ExitCode() == 1);
  CHECK(BatchOf({Verdict::kCrashed, Verdict::kError, Verdict::kDiffering}).ExitCode() == 5);
  CHECK(BatchOf({Verdict::kError, Verdict::kDiffering}).ExitCode() == 2);
}

TEST_CASE("A batch counts each verdict and keeps its records in the batch's order", "[run]") {
  const run::BatchResult empty;
  CHECK(empty.Scenes() == 0);
  CHECK_FALSE(empty.Worst().has_value());
  CHECK(empty.ExitCode() == 0);

  const run::BatchResult batch = BatchOf({Verdict::kIdentical, Verdict::kDiffering, Verdict::kIdentical,
                                          Verdict::kInconclusive, Verdict::kError, Verdict::kRendered});
  CHECK(batch.Scenes() == 6);
  CHECK(batch.Count(Verdict::kIdentical) == 2);
  CHECK(batch.Count(Verdict::kDiffering) == 1);
  CHECK(batch.Count(Verdict::kInconclusive) == 1);
  CHECK(batch.Count(Verdict::kError) == 1);
  CHECK(batch.Count(Verdict::kRendered) == 1);
  CHECK(batch.Count(Verdict::kCrashed) == 0);
  CHECK(batch.Count(Verdict::kVerified) == 0);
  std::size_t counted = 0;
  for (Verdict v : kAll) counted += batch.Count(v);
  CHECK(counted == batch.Scenes());
  CHECK(batch.Worst() == Verdict::kError);
  CHECK(batch.ExitCode() == 2);
  REQUIRE(batch.Records().size() == 6);
  CHECK(batch.Records()[0].scene == "s0");
  CHECK(batch.Records()[4].verdict == Verdict::kError);
  CHECK(batch.Records()[5].scene == "s5");
}
