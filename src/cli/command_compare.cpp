// `twinraster compare A.png B.png`: counts differing pixels, optionally writing a diff image.
#include "base/usage_error.hpp"
#include "cli/commands.hpp"
#include "cli/io_arguments.hpp"
#include "cli/output_paths.hpp"
#include "cli/parser_setup.hpp"
#include "image/image_compare.hpp"
#include "image/png_file.hpp"
#include "report/comparison_report.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace twinraster {

namespace {

struct CompareArguments {
  std::string a, b;
  std::optional<std::string> diff;
  bool json = false;
};

bool DiffToStandardOutput(const CompareArguments& args) { return args.diff && IsStandardStream(*args.diff); }

// The diff's destination, checked (its directories made) before any image is read; -: standard
// output, not a terminal, and the report then goes to standard error.
void PrepareDiff(const CompareArguments& args) {
  if (!args.diff) return;
  if (DiffToStandardOutput(args)) {
    if (args.json) throw UsageError("--diff - and --json both want standard output: drop one of them");
    if (StandardOutputIsTerminal()) {
      throw UsageError(
          "--diff -: standard output is a terminal; redirect it (> diff.png) or pipe it to another program");
    }
    return;
  }
  ExpectPngName("--diff", *args.diff);
  OutputPaths paths;
  paths.File("--diff " + *args.diff, *args.diff);
  paths.MakeDirectories();
}

int Compare(const CompareArguments& args) {
  PrepareDiff(args);
  const Image a = ReadPng(args.a);
  const Image b = ReadPng(args.b);
  const Comparison comparison = CompareImages(a, b);
  const bool wrote_diff = args.diff && comparison.same_size && !comparison.Equal();
  if (wrote_diff && DiffToStandardOutput(args)) {
    WriteStandardOutput(EncodePng(DiffImage(a, b)));
  } else if (wrote_diff) {
    WritePng(*args.diff, DiffImage(a, b));
  }
  // A diff left by an earlier run would now describe images that no longer differ.
  std::error_code ignored;
  if (args.diff && !DiffToStandardOutput(args) && comparison.Equal() &&
      std::filesystem::is_regular_file(*args.diff, ignored)) {
    std::filesystem::remove(*args.diff, ignored);
  }

  if (args.json) {
    std::cout
        << report::CompareJson({args.a, a}, {args.b, b}, comparison, wrote_diff ? args.diff : std::nullopt).dump(2)
        << "\n";
  } else {
    const std::string diff_name = DiffToStandardOutput(args) ? "standard output" : args.diff.value_or("");
    (DiffToStandardOutput(args) ? std::cerr : std::cout)
        << report::ComparisonText(a, b, comparison) << (wrote_diff ? ", diff in " + diff_name : "") << "\n";
  }
  return comparison.Equal() ? kExitOk : kExitImagesDiffer;
}

}  // namespace

CommandRun AddCompareCommand(CLI::App& app) {
  auto a = std::make_shared<CompareArguments>();
  CLI::App* command = AddSubcommand(app, "compare", "count the pixels that differ between two PNGs",
                                    "Exit codes: 0 identical, 1 the images differ (or their sizes do), 2 bad input or\n"
                                    "usage, 4 internal error.");
  command->add_option("A.png", a->a, "the first image")->required();
  command->add_option("B.png", a->b, "the second image")->required();
  command
      ->add_option("--diff", a->diff,
                   "when they differ, write D.png: differing pixels in red over a faded A;\n"
                   "- writes it to standard output, and the report to standard error")
      ->type_name("D.png");
  command->add_flag("--json", a->json, "print one JSON object (twinraster.compare/1, docs/json-output.md)");
  return [a] { return Compare(*a); };
}

}  // namespace twinraster
