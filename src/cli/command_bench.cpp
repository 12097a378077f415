// `twinraster bench`: runs the suite, prints the table and summary, and with --out writes
// bench.csv, bench.svg, bench.json and bench.txt (all staged, so all or none are replaced).
#include "bench/bench_report.hpp"
#include "bench/bench_suite.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "image/staged_file.hpp"
#include "base/usage_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>

namespace twinraster {

int BenchCommand(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--json"}, {"--out", "--runs", "--only", "--scenes", "--methods"});
  cl.ExpectPositional({});
  BenchOptions options;
  if (auto runs = cl.Index("--runs")) {
    if (*runs < 1 || *runs > 1000) throw UsageError("--runs must be 1..1000");
    options.runs = static_cast<int>(*runs);
  }
  options.only = cl.Option("--only");
  if (auto methods = cl.Option("--methods")) {
    const std::vector<std::string> known = BenchMethodNames();
    std::string rest = *methods;
    while (!rest.empty()) {
      const std::size_t comma = rest.find(',');
      const std::string name = rest.substr(0, comma);
      rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        std::string all;
        for (const std::string& k : known) all += (all.empty() ? "" : ", ") + k;
        throw UsageError("--methods: unknown method \"" + name + "\"; known: " + all);
      }
      options.methods.push_back(name);
    }
  }
  if (auto scenes = cl.Option("--scenes")) options.scenes_dir = *scenes;
  if (!std::filesystem::is_directory(options.scenes_dir)) {
    throw UsageError("no scene directory " + options.scenes_dir.string() + " (run from the repository root, or pass --scenes DIR)");
  }
  const std::optional<std::string> out = cl.Option("--out");
  if (out && !std::filesystem::is_directory(*out)) {
    std::error_code error;
    std::filesystem::create_directories(*out, error);
    if (error) throw FileError(*out + ": cannot create the directory: " + error.message());
  }

  const BenchResult result = RunBench(options);
  if (out) {
    const std::filesystem::path dir = *out;
    // Staged together: either every output is replaced or none is.
    std::vector<StagedFile> staged;
    staged.emplace_back(dir / "bench.csv", BenchCsv(result));
    staged.emplace_back(dir / "bench.svg", BenchChartSvg(result));
    staged.emplace_back(dir / "bench.json", BenchJson(result).dump(2) + "\n");
    staged.emplace_back(dir / "bench.txt", BenchTable(result));
    for (StagedFile& file : staged) file.Commit();
  }
  if (cl.Flag("--json")) {
    std::cout << BenchJson(result).dump(2) << "\n";
  } else {
    std::cout << BenchTable(result);
  }
  return kExitOk;
}

}  // namespace twinraster
