// `twinraster compare A.png B.png`: counts differing pixels, optionally writing a diff image; both
// headers are checked before either file is decoded, and the files are read a row at a time.
#include "base/usage_error.hpp"
#include "cli/commands.hpp"
#include "cli/io_arguments.hpp"
#include "cli/output_paths.hpp"
#include "cli/parser_setup.hpp"
#include "files/png_file.hpp"
#include "image/image_compare.hpp"
#include "run_report/comparison_report.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace twinraster::cli {

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

// Every row of a file read and checked, none kept: a file of another size is still refused
// when it is corrupt, as one compared would be.
void CheckRows(files::PngRowReader& file) {
  for (std::uint32_t y = 0; y < file.Size().height; ++y) file.NextRow();
  file.Finish();
}

// The two files compared a row at a time, the diff's rows drawn into `diff` when given.
Comparison CompareRows(files::PngRowReader& a, files::PngRowReader& b, Image* diff) {
  Comparison c;
  const files::PngSize size = a.Size();
  for (std::uint32_t y = 0; y < size.height; ++y) {
    const std::uint8_t *row_a = a.NextRow(), *row_b = b.NextRow();
    CompareRow(row_a, row_b, size.width, c);
    if (diff) DiffRow(row_a, row_b, size.width, diff->pixel(0, y));
  }
  a.Finish();
  b.Finish();
  return c;
}

int Compare(const CompareArguments& args) {
  ExpectImageFile("A.png", args.a);
  ExpectImageFile("B.png", args.b);
  PrepareDiff(args);
  // Both headers before either file is decoded: a refusal, or sizes that differ, cost nothing.
  const files::PngSize size_a = files::ReadPngSize(args.a), size_b = files::ReadPngSize(args.b);
  const bool same_size = size_a == size_b;
  const std::uint64_t pixels = std::uint64_t{size_a.width} * size_a.height;
  if (args.diff && same_size && pixels > files::kMaxWholePixels) {
    throw UsageError("--diff " + *args.diff + ": a diff image is drawn whole, for at most " +
                     std::to_string(files::kMaxWholePixels) + " pixels, and these are " + std::to_string(size_a.width) +
                     " x " + std::to_string(size_a.height) + ": compare them without --diff");
  }
  // Read a row at a time, never whole: memory stays a few rows, whatever size the files declare.
  files::PngRowReader a(args.a), b(args.b);
  Comparison comparison;
  std::optional<Image> diff;
  if (!same_size) {
    comparison.same_size = false;
    CheckRows(a);
    CheckRows(b);
  } else {
    if (args.diff) diff.emplace(size_a.width, size_a.height, Image::Uncleared{});
    comparison = CompareRows(a, b, diff ? &*diff : nullptr);
  }
  const bool wrote_diff = diff && !comparison.Equal();
  if (wrote_diff && DiffToStandardOutput(args)) {
    WriteStandardOutput(files::EncodePng(*diff));
  } else if (wrote_diff) {
    files::WritePng(*args.diff, *diff);
  }
  // A diff left by an earlier run would now describe images that no longer differ.
  std::error_code ignored;
  if (args.diff && !DiffToStandardOutput(args) && comparison.Equal() &&
      std::filesystem::is_regular_file(*args.diff, ignored)) {
    std::filesystem::remove(*args.diff, ignored);
  }

  const run_report::NamedImage named_a{args.a, size_a.width, size_a.height},
      named_b{args.b, size_b.width, size_b.height};
  if (args.json) {
    std::cout << run_report::CompareJson(named_a, named_b, comparison, wrote_diff ? args.diff : std::nullopt).dump(2)
              << "\n";
  } else {
    const std::string diff_name = DiffToStandardOutput(args) ? "standard output" : args.diff.value_or("");
    (DiffToStandardOutput(args) ? std::cerr : std::cout) << run_report::ComparisonText(named_a, named_b, comparison)
                                                         << (wrote_diff ? ", diff in " + diff_name : "") << "\n";
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

}  // namespace twinraster::cli
