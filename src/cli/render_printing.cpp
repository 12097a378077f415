#include "cli/render_printing.hpp"

#include "cli/io_arguments.hpp"
#include "run_report/render_outputs.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

namespace twinraster::cli {

void PrintRecord(const RenderArguments& a, const run::RunRecord& record, bool several) {
  if (a.json) {
    std::cout << (several ? run_report::RenderJson(record).dump() : run_report::RenderJson(record).dump(2)) << "\n"
              << std::flush;
    return;
  }
  // Standard output carries the PNG (-o -) or the JUnit XML (--junit -) alone.
  const bool to_stdout =
      (!several && a.output && IsStandardStream(*a.output)) || (a.junit && IsStandardStream(*a.junit));
  if (to_stdout && a.quiet) return;
  (to_stdout ? std::cerr : std::cout) << run_report::RenderText(record, a.verify) << std::flush;
}

void PrintFailure(const RenderArguments& a, const std::string& message, const run::RunRecord& record, bool several) {
  std::cerr << "twinraster: " << message << "\n";
  if (a.json) PrintRecord(a, record, several);
}

}  // namespace twinraster::cli
