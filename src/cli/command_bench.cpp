// `twinraster bench`: runs the suite, prints the table and summary, and with --out writes
// bench.csv, bench.svg, bench.html, bench.json and bench.txt (all staged, so all or none are
// replaced); --html and --svg write the page or the plot anywhere. --scale, --verify and --loaders
// run the other benches instead.
#include "base/counted.hpp"
#include "base/usage_error.hpp"
#include "bench/bench_suite.hpp"
#include "bench/loader_bench.hpp"
#include "bench/scale_bench.hpp"
#include "bench/verify_bench.hpp"
#include "bench_report/bench_pages.hpp"
#include "bench_report/bench_tables.hpp"
#include "cli/commands.hpp"
#include "cli/io_arguments.hpp"
#include "cli/output_paths.hpp"
#include "cli/parser_setup.hpp"
#include "cli/progress.hpp"
#include "files/staged_file.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

namespace twinraster::cli {

namespace {

struct BenchArguments {
  std::optional<std::string> out;
  int runs = 15;
  std::optional<std::string> only;
  std::vector<std::string> methods;
  std::string scenes = "scenes";
  bool json = false;
  bool quiet = false;
  bool scale = false;
  bool verify = false;
  bool loaders = false;
  std::string gltf = bench::kDefaultLoaderBenchAsset;  // --loaders' asset
  std::optional<std::string> html, svg;                // the page, the plot
  std::vector<std::size_t> counts = {1'000, 10'000, 100'000, 1'000'000};
  std::size_t batch_scenes = 1000;  // --scale's batch of small scenes
};

// The files each bench writes into --out, in the order its WriteTogether() call gives their texts.
std::vector<std::string> OutFiles(const BenchArguments& a) {
  if (a.scale) return {"scale.csv", "scale.svg", "scale-stages.svg", "scale.html", "scale.json", "scale.txt"};
  if (a.verify) return {"verify.json", "verify.txt"};
  if (a.loaders) return {"loaders.json", "loaders.txt"};
  return {"bench.csv", "bench.svg", "bench.html", "bench.json", "bench.txt"};
}

bool ToStandardOutput(const std::optional<std::string>& file) { return file && IsStandardStream(*file); }

// Where the table goes: standard error when --html - or --svg - takes standard output.
std::ostream& TableStream(const BenchArguments& a) {
  return ToStandardOutput(a.html) || ToStandardOutput(a.svg) ? std::cerr : std::cout;
}

// Staged together: either every output (in --out, and --html and --svg) is replaced or none is.
// `in_out`: the texts of OutFiles(a), in order.
void WriteTogether(const BenchArguments& a, const std::vector<std::string>& in_out, const std::string& page,
                   const std::string& plot) {
  std::vector<files::StagedFile> staged;
  if (a.out) {
    const std::vector<std::string> names = OutFiles(a);
    for (std::size_t i = 0; i < names.size() && i < in_out.size(); ++i) {
      staged.emplace_back(std::filesystem::path(*a.out) / names[i], in_out[i]);
    }
  }
  if (a.html && !ToStandardOutput(a.html)) staged.emplace_back(*a.html, page);
  if (a.svg && !ToStandardOutput(a.svg)) staged.emplace_back(*a.svg, plot);
  for (files::StagedFile& file : staged) file.Commit();
  if (ToStandardOutput(a.html)) WriteStandardOutput(page);
  if (ToStandardOutput(a.svg)) WriteStandardOutput(plot);
}

// Every destination checked, and --out's directories made, before the minutes of measuring.
void PrepareOutputs(const BenchArguments& a) {
  if (ToStandardOutput(a.out)) throw UsageError("--out -: the results are several files; give a directory");
  if (ToStandardOutput(a.html) && ToStandardOutput(a.svg))
    throw UsageError("--html - and --svg -: standard output takes one of them; give the other a file");
  if ((ToStandardOutput(a.html) || ToStandardOutput(a.svg)) && a.json) {
    throw UsageError(std::string(ToStandardOutput(a.html) ? "--html -" : "--svg -") +
                     " and --json both want standard output: drop one of them");
  }
  OutputPaths paths;
  if (a.out) {
    paths.Directory("--out " + *a.out, *a.out);
    for (const std::string& name : OutFiles(a)) paths.File("--out " + *a.out, std::filesystem::path(*a.out) / name);
  }
  if (a.html && !ToStandardOutput(a.html)) paths.File("--html " + *a.html, *a.html);
  if (a.svg && !ToStandardOutput(a.svg)) paths.File("--svg " + *a.svg, *a.svg);
  paths.MakeDirectories();
}

// bench --scale: the million cubes at growing instance counts.
int BenchScale(const BenchArguments& a) {
  bench::ScaleOptions options;
  options.counts = a.counts;
  options.runs = a.runs;
  // Fixed costs: this very executable, started as a user starts it, on the suite's chapter scene
  // (not measured without it: the table says so).
  const std::filesystem::path chapter = std::filesystem::path(a.scenes) / "cgfs-transforms.json";
  if (std::filesystem::is_regular_file(chapter)) {
    options.processes = bench::ProcessBenchOptions{.executable = std::filesystem::read_symlink("/proc/self/exe"),
                                                   .chapter_scene = chapter,
                                                   .runs = std::max(a.runs, 5),
                                                   .batch_runs = std::min(a.runs, 5),
                                                   .batch_scenes = a.batch_scenes};
  }
  Progress progress = Progress::OnStandardError(a.quiet);
  if (progress.active()) {
    options.on_row = [&progress](const bench::ScaleRow& row, std::size_t done, std::size_t total) {
      progress.Line("scale " + std::to_string(done) + "/" + std::to_string(total) + ": " +
                    Counted(row.instances, "instance"));
    };
  }
  const bench::ScaleResult result = bench::RunScaleBench(options);
  const std::string table = bench_report::ScaleTable(result), plot = bench_report::ScaleChartSvg(result);
  const std::string page = bench_report::ScalePageHtml(result, table);
  WriteTogether(a,
                {bench_report::ScaleCsv(result), plot, bench_report::ScaleStagesSvg(result), page,
                 bench_report::ScaleJson(result).dump(2) + "\n", table},
                page, plot);
  if (a.json)
    std::cout << bench_report::ScaleJson(result).dump(2) << "\n";
  else
    TableStream(a) << bench_report::ScaleTable(result);
  return kExitOk;
}

// bench --verify: the twin's render against the verifier's judgement of it.
int BenchVerify(const BenchArguments& a) {
  std::vector<std::filesystem::path> scenes;
  for (const auto& file : bench::DefaultVerifyBenchScenes(a.scenes)) {
    if (!a.only || file.string().find(*a.only) != std::string::npos) scenes.push_back(file);
  }
  if (scenes.empty()) throw UsageError("--only " + a.only.value_or("") + ": none of the verify bench's scenes");
  for (const auto& file : scenes) {
    if (!std::filesystem::is_regular_file(file)) {
      throw UsageError("no scene " + file.string() + " (run from the repository root, or pass --scenes DIR)");
    }
  }
  Progress progress = Progress::OnStandardError(a.quiet);
  progress.Status("verify bench: " + Counted(scenes.size(), "scene") + ", " + Counted(a.runs, "run") + "...");
  // The whole processes are this very executable, started as a user starts it.
  const bench::VerifyBenchResult result =
      bench::RunVerifyBench(scenes, a.runs, std::filesystem::read_symlink("/proc/self/exe"));
  progress.Clear();
  WriteTogether(a, {bench_report::VerifyBenchJson(result).dump(2) + "\n", bench_report::VerifyBenchTable(result)}, "",
                "");
  if (a.json)
    std::cout << bench_report::VerifyBenchJson(result).dump(2) << "\n";
  else
    std::cout << bench_report::VerifyBenchTable(result);
  return kExitOk;
}

// bench --loaders: a glTF asset against the same scene as JSON, file to Scene.
int BenchLoaders(const BenchArguments& a) {
  if (!std::filesystem::is_regular_file(a.gltf)) {
    throw UsageError(
        "--gltf " + a.gltf + ": no such file" +
        (a.gltf == bench::kDefaultLoaderBenchAsset ? " (Debian's assimp-testmodels: scripts/setup.sh --tests)" : ""));
  }
  Progress progress = Progress::OnStandardError(a.quiet);
  progress.Status("loaders bench: " + a.gltf + ", " + Counted(a.runs, "run") + "...");
  const bench::LoaderBenchResult result =
      bench::RunLoaderBench({.gltf = a.gltf,
                             .runs = a.runs,
                             .memory_runs = std::min(a.runs, 5),
                             .executable = std::filesystem::read_symlink("/proc/self/exe")});
  progress.Clear();
  const std::string table = bench_report::LoaderBenchTable(result),
                    json = bench_report::LoaderBenchJson(result).dump(2) + "\n";
  WriteTogether(a, {json, table}, "", "");
  std::cout << (a.json ? json : table);
  return kExitOk;
}

int Bench(const BenchArguments& a) {
  if ((a.verify || a.loaders) && (a.html || a.svg))
    throw UsageError(std::string("--html and --svg plot the suite or --scale; bench ") +
                     (a.verify ? "--verify" : "--loaders") + " prints a table");
  if (int(a.scale) + int(a.verify) + int(a.loaders) > 1)
    throw UsageError("--scale, --verify and --loaders are three benches: one at a time");
  PrepareOutputs(a);
  if (a.scale) return BenchScale(a);
  if (a.verify) return BenchVerify(a);
  if (a.loaders) return BenchLoaders(a);
  bench::BenchOptions options;
  options.runs = a.runs;
  options.only = a.only;
  options.methods = a.methods;
  options.scenes_dir = a.scenes;
  if (!std::filesystem::is_directory(options.scenes_dir)) {
    throw UsageError("no scene directory " + options.scenes_dir.string() +
                     " (run from the repository root, or pass --scenes DIR)");
  }
  Progress progress = Progress::OnStandardError(a.quiet);
  if (progress.active()) {
    options.on_row = [&progress](const bench::BenchRow& row, std::size_t done, std::size_t total) {
      progress.Line(bench_report::BenchProgressLine(row, done, total));
    };
  }
  const bench::BenchResult result = bench::RunBench(options);
  const std::string table = bench_report::BenchTable(result), plot = bench_report::BenchChartSvg(result);
  const std::string page = bench_report::BenchPageHtml(result, table);
  WriteTogether(a, {bench_report::BenchCsv(result), plot, page, bench_report::BenchJson(result).dump(2) + "\n", table},
                page, plot);
  if (a.json) {
    std::cout << bench_report::BenchJson(result).dump(2) << "\n";
  } else {
    TableStream(a) << bench_report::BenchTable(result);
  }
  return kExitOk;
}

}  // namespace

CommandRun AddBenchCommand(CLI::App& app) {
  auto a = std::make_shared<BenchArguments>();
  CLI::App* command =
      AddSubcommand(app, "bench", "time each way of computing the chain, and its error against the truth",
                    "The suite is SCENES/*.json, SCENES/hard/*.json and SCENES/bench/*.json. On a terminal, each\n"
                    "row shows on standard error as it finishes.\n"
                    "Exit codes: 0 done, 2 bad input or usage, 3 no usable Vulkan device (leave lavapipe and\n"
                    "swiftshader out of --methods to need none), 4 internal error.");
  command->add_option("--out", a->out, "also write bench.csv, bench.svg, bench.html, bench.json and bench.txt into DIR")
      ->type_name("DIR");
  command
      ->add_option("--html", a->html,
                   "also write a page (self-contained, inline SVG) plotting each method's time against\n"
                   "its error for every scene; with --scale, cost against instance count; - writes\n"
                   "it to standard output, and the table to standard error")
      ->type_name("FILE");
  command->add_option("--svg", a->svg, "also write the main plot alone as an SVG file (- : to standard output)")
      ->type_name("FILE");
  ExpectIntegerIn(command->add_option("--runs", a->runs, "timed runs per median (default: 15)")->type_name("N"), 1,
                  1000);
  command->add_option("--only", a->only, "only the scenes whose path contains TEXT")->type_name("TEXT");
  std::vector<std::string> methods = bench::BenchMethodNames();
  std::string method_list;
  for (const std::string& m : methods) method_list += (method_list.empty() ? "" : ", ") + m;
  ExpectOneOf(
      command->add_option("--methods", a->methods, "only these rows, comma-separated (default: all):\n" + method_list)
          ->option_text("A,B")
          ->delimiter(',')
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll),
      "method", methods);
  command->add_option("--scenes", a->scenes, "the suite's directory (default: scenes)")->type_name("DIR");
  command->add_flag("--json", a->json, "print the results as JSON (twinraster.bench/2, docs/json-output.md)");
  command->add_flag("-q,--quiet", a->quiet, "no progress on standard error");
  command->add_flag("--scale", a->scale,
                    "instead of the suite: cubes written out one instance each, at growing counts,\n"
                    "every stage timed (the verifier too), with peak memory; each size's frame by\n"
                    "every PNG encoder; and first a scene's fixed costs as whole processes (scale.csv/\n"
                    ".svg/.html/.json/.txt with --out; JSON twinraster.bench-scale/4)");
  command->add_flag("--verify", a->verify,
                    "instead of the suite: the CPU twin's render against the verifier's judgement\n"
                    "of that image, on the chapter's scene, lit-gouraud and the million cubes, in\n"
                    "process and as whole processes (render, then verify of an image that passes and\n"
                    "of one that fails) (verify.json/.txt with --out; JSON twinraster.bench-verify/2)");
  command->add_flag("--loaders", a->loaders,
                    "instead of the suite: a glTF asset (--gltf) against the same scene written as a JSON\n"
                    "scene file: load time and memory per triangle, in process and as whole processes\n"
                    "(loaders.json/.txt with --out; JSON twinraster.bench-loaders/1)");
  command
      ->add_option("--gltf", a->gltf,
                   std::string("with --loaders: the .glb or .gltf file (default: assimp-testmodels'\n") +
                       bench::kDefaultLoaderBenchAsset + ")")
      ->type_name("FILE");
  command->add_option("--counts", a->counts, "with --scale: the instance counts (default: 1000,10000,100000,1000000)")
      ->type_name("N,N")
      ->delimiter(',');
  command
      ->add_option("--batch-scenes", a->batch_scenes,
                   "with --scale: the small scenes in the fixed costs' batch (default: 1000); the fixed\n"
                   "costs are measured when SCENES/cgfs-transforms.json is there (--scenes DIR)")
      ->type_name("N");
  return [a] { return Bench(*a); };
}

}  // namespace twinraster::cli
