// A batch of scenes' runs as every batch output reads it (the batch page, the JUnit file, render's
// JSON lines, the exit code): the records in the batch's order, how many got each verdict, and the
// worst verdict, as deqp-runner keeps its results. It runs, prints and formats nothing: cli/ fills
// it, run_report/ writes it.
#pragma once

#include "run/run_record.hpp"
#include "run/verdict.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace twinraster::run {

// How bad a verdict is for a batch, higher being worse. The ranking, best to worst:
//   identical, verified, rendered   (success, exit 0)
//   inconclusive                    (exit 6: milder than every problem, worse than success)
//   differing, error, crashed       (exits 1, 2 and 5: the problems in the order of their codes)
// so that the batch's exit code, ExitCodeOf(the worst verdict), is the one the scenes' exit codes
// have always given. It is not the page's order (verdict.hpp's enum), which lists error first.
int Severity(Verdict verdict);

// Of two verdicts, the one Severity ranks worse (`a` when they tie).
Verdict Worse(Verdict a, Verdict b);

class BatchResult {
 public:
  // Adds a scene's record at the end, its verdict decided.
  void Add(RunRecord record);

  const std::vector<RunRecord>& Records() const { return records_; }
  std::size_t Scenes() const { return records_.size(); }
  std::size_t Count(Verdict verdict) const { return counts_[static_cast<std::size_t>(verdict)]; }
  // The worst of the scenes' verdicts; none for an empty batch.
  std::optional<Verdict> Worst() const { return worst_; }
  // The batch's exit code: the worst verdict's (ExitCodeOf), 0 for an empty batch.
  int ExitCode() const;

  double total_ms = 0;  // the whole batch, wall clock: set once its scenes are done

 private:
  std::vector<RunRecord> records_;
  std::array<std::size_t, kVerdictCount> counts_{};
  std::optional<Verdict> worst_;
};

}  // namespace twinraster::run
