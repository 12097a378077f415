// The one verdict: each way a run can end, decided from its record, and what counts as success.
#include "run/run_record.hpp"
#include "support/catch.hpp"

using namespace twinraster;

namespace {

run::RunRecord BothDrawn(std::uint64_t differing) {
  run::RunRecord r;
  r.backends.resize(2);
  r.backends[0].backend = run::Backend::kGpu;
  r.comparison = Comparison{true, differing, differing ? 3 : 0};
  return r;
}

verify::Verification Judged(std::uint64_t violations, std::uint64_t background_excluded) {
  verify::Verification v;
  v.violations = violations, v.covered = 50, v.certain = 3000, v.background_excluded = background_excluded;
  return v;
}

}  // namespace

TEST_CASE("VerdictOf: errors, crashes, violations and broken promises fail, and judgements decide the rest", "[run]") {
  CHECK(run::VerdictOf(run::ErrorRecord("a.json", "a.json: line 1: bad")) == run::Verdict::kError);
  CHECK(run::ErrorRecord("dir/a.json", "x").name == "a");

  run::RunRecord crashed = BothDrawn(0);
  crashed.backends[0].status = run::BackendStatus::kTimedOut;
  CHECK(run::VerdictOf(crashed) == run::Verdict::kCrashed);

  CHECK(run::VerdictOf(BothDrawn(0)) == run::Verdict::kIdentical);
  CHECK(run::VerdictOf(BothDrawn(5)) == run::Verdict::kDiffering);  // nothing judged the difference

  run::RunRecord promised = BothDrawn(5);
  promised.twin = twin_rules::TwinRules{};
  promised.twin->exact = true;
  promised.verification = Judged(0, 40);
  CHECK(run::VerdictOf(promised) == run::Verdict::kDiffering);  // the twin copies this driver exactly

  run::RunRecord allowed = BothDrawn(5);
  allowed.verification = Judged(0, 40);
  CHECK(run::VerdictOf(allowed) == run::Verdict::kVerified);
  allowed.verification = Judged(0, 0);  // an empty image would pass too
  CHECK(run::VerdictOf(allowed) == run::Verdict::kInconclusive);
  allowed.verification = Judged(2, 40);
  CHECK(run::VerdictOf(allowed) == run::Verdict::kDiffering);

  run::RunRecord alone;
  alone.backends.resize(1);
  CHECK(run::VerdictOf(alone) == run::Verdict::kRendered);
}

TEST_CASE("Verdicts: failures, inconclusive and success are three kinds, and each has its name", "[run]") {
  using run::Verdict;
  for (Verdict v : {Verdict::kError, Verdict::kCrashed, Verdict::kDiffering}) {
    CHECK(run::IsFailure(v));
    CHECK_FALSE(run::IsSuccess(v));
  }
  CHECK(run::IsInconclusive(Verdict::kInconclusive));
  CHECK_FALSE(run::IsSuccess(Verdict::kInconclusive));
  CHECK_FALSE(run::IsFailure(Verdict::kInconclusive));
  for (Verdict v : {Verdict::kVerified, Verdict::kIdentical, Verdict::kRendered}) CHECK(run::IsSuccess(v));
  CHECK(run::VerdictOf(verify::Judgement::kPassed) == Verdict::kVerified);
  CHECK(run::VerdictOf(verify::Judgement::kInconclusive) == Verdict::kInconclusive);
  CHECK(run::VerdictOf(verify::Judgement::kFailed) == Verdict::kDiffering);
  CHECK(std::string(run::VerdictName(Verdict::kInconclusive)) == "inconclusive");
  // Each verdict's exit code, which render's JSON reports per scene (docs/commands.md).
  CHECK(run::ExitCodeOf(Verdict::kError) == 2);
  CHECK(run::ExitCodeOf(Verdict::kCrashed) == 5);
  CHECK(run::ExitCodeOf(Verdict::kDiffering) == 1);
  CHECK(run::ExitCodeOf(Verdict::kInconclusive) == 6);
  for (Verdict v : {Verdict::kVerified, Verdict::kIdentical, Verdict::kRendered}) CHECK(run::ExitCodeOf(v) == 0);
  CHECK(std::string(run::StatusName(run::BackendStatus::kTimedOut)) == "timed out");
  CHECK(std::string(run::BackendName(run::Backend::kGpu)) == "gpu");
}
