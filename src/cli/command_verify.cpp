// `twinraster verify SCENE IMAGE.png`: judges any image of the scene by what a conformant Vulkan
// implementation may draw (verify/verifier.hpp), by the rules of the device that drew it (the
// image's own notes, or the options), writes the verification map, exits 0, 1 or 6. With --coverage
// it judges only where the image is covered (run/judge_coverage.hpp).
#include "base/usage_error.hpp"
#include "cli/colour_argument.hpp"
#include "cli/commands.hpp"
#include "cli/io_arguments.hpp"
#include "cli/output_paths.hpp"
#include "cli/parser_setup.hpp"
#include "cli/scene_choice_options.hpp"
#include "files/png_file.hpp"
#include "run/device_rules.hpp"
#include "run/judge_coverage.hpp"
#include "run/judge_image.hpp"
#include "run_report/coverage_report.hpp"
#include "run_report/image_notes.hpp"
#include "run_report/verify_report.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>
#include <memory>

namespace twinraster::cli {

namespace {

struct VerifyArguments {
  std::string scene, image;
  std::optional<std::string> map;
  bool no_map = false;
  bool wireframe = false;
  int subpixel_bits = 4;  // the spec's minimum subPixelPrecisionBits
  std::string strict_lines = "false";
  bool bits_given = false, strict_given = false;
  bool json = false;
  SceneChoiceArguments choice;                            // --camera, --scene, --size
  bool coverage = false;                                  // judge coverage only
  std::optional<std::string> background, hole_tolerance;  // --coverage's, parsed by colour_argument.hpp
};

// The Vulkan spec's least subPixelPrecisionBits (its "Required Limits" table): no conformant device
// snaps coarser, so fewer bits would judge by rules no device has.
constexpr int kMinSubpixelBits = 4;

// --subpixel-bits below the spec's minimum, refused with the reason (ExpectIntegerIn names the range).
std::string BelowSpecMinimum(std::string& value) {
  return value.size() == 1 && value[0] >= '0' && value[0] < '0' + kMinSubpixelBits
             ? "Vulkan requires subPixelPrecisionBits of at least " + std::to_string(kMinSubpixelBits) +
                   " (the spec's Required Limits), got " + value
             : "";
}

// The device's rules: each option given, else what the image's notes say, else the loosest.
run::DeviceRules DeviceRulesOf(const VerifyArguments& a, const std::optional<verify::DrawnBy>& drawn_by) {
  return run::ChooseDeviceRules(drawn_by, a.bits_given ? std::optional<int>(a.subpixel_bits) : std::nullopt,
                                a.strict_given ? std::optional<bool>(a.strict_lines == "true") : std::nullopt);
}

bool MapToStandardOutput(const VerifyArguments& a) { return a.map && IsStandardStream(*a.map) && !a.no_map; }

// Where the map goes, checked (and its directories made) before the scene is read: a map that
// cannot be written fails at once, not after the judgement. -: standard output, not a terminal.
void PrepareMap(const VerifyArguments& a) {
  if (a.map && !IsStandardStream(*a.map)) ExpectPngName("--map", *a.map);
  if (a.no_map) return;
  if (MapToStandardOutput(a)) {
    if (a.json) throw UsageError("--map - and --json both want standard output: drop one of them");
    if (StandardOutputIsTerminal()) {
      throw UsageError("--map -: standard output is a terminal; redirect it (> map.png) or pipe it to another program");
    }
    return;
  }
  OutputPaths paths;
  paths.File(a.map ? "--map " + *a.map : "the map beside IMAGE.png (--map MAP.png or --no-map to change it)",
             a.map.value_or(Suffixed(a.image, "map")));
  paths.MakeDirectories();
}

// Writes the map, staged, or to standard output; returns what the report calls it.
std::string WriteMap(const VerifyArguments& a, const Image& map) {
  if (MapToStandardOutput(a)) {
    WriteStandardOutput(files::EncodePng(map));
    return "standard output";
  }
  const std::string file = a.map.value_or(Suffixed(a.image, "map"));
  files::StagePng(file, map).Commit();
  return file;
}

// The report goes to standard error when standard output carries the map.
std::ostream& ReportStream(const VerifyArguments& a) { return MapToStandardOutput(a) ? std::cerr : std::cout; }

// --coverage's run: the same image and rules, judged by where it is covered.
int VerifyCoverage(const VerifyArguments& a, const Scene& scene, const Image& image,
                   const std::optional<verify::DrawnBy>& drawn_by, verify::CoverageOptions options) {
  const run::DeviceRules rules = DeviceRulesOf(a, drawn_by);
  options.rules = rules.rules;
  const run::CoverageJudgement judgement = run::JudgeCoverage(scene, image, options, !a.no_map);
  std::optional<std::string> map;
  if (judgement.map) map = WriteMap(a, *judgement.map);
  const run_report::CoverageReport outputs{a.scene, a.image, scene.wireframe, drawn_by, rules, judgement, map};
  if (a.json)
    std::cout << run_report::CoverageJson(outputs).dump(2) << "\n";
  else
    ReportStream(a) << run_report::CoverageReportText(outputs);
  return ExitCodeOf(judgement.verdict);
}

int Verify(const VerifyArguments& a) {
  ExpectImageFile("IMAGE.png", a.image);
  if (a.map && a.no_map)
    throw UsageError("--map " + *a.map + " writes the map and --no-map writes none: give one of them");
  PrepareMap(a);
  // --coverage's options are checked before the scene is read, so that a mistake costs nothing.
  verify::CoverageOptions coverage;
  if (!a.coverage && (a.background || a.hole_tolerance))
    throw UsageError(std::string(a.background ? "--background" : "--hole-tolerance") + " needs --coverage");
  if (a.background) coverage.background = ParseColourArgument("--background", *a.background);
  if (a.hole_tolerance) coverage.hole_tolerance_percent = ParsePercentArgument("--hole-tolerance", *a.hole_tolerance);
  Scene scene = LoadSceneArgument(a.scene, ChoiceOf(a.choice));
  PrintSceneNotes(scene, a.scene);
  if (a.wireframe) scene.wireframe = true;
  // The canvas is the size the image must declare, checked before any pixel is decoded.
  const Image image = files::ReadPng(a.image, [&](std::uint32_t width, std::uint32_t height) {
    if (width != scene.canvas.width || height != scene.canvas.height) {
      throw files::FileError(a.image + ": the image is " + std::to_string(width) + " x " + std::to_string(height) +
                             ", but " + a.scene + " draws a canvas of " + std::to_string(scene.canvas.width) + " x " +
                             std::to_string(scene.canvas.height));
    }
  });
  const std::optional<verify::DrawnBy> drawn_by = run_report::DrawnByOf(files::ReadPngNotes(a.image));
  if (a.coverage) return VerifyCoverage(a, scene, image, drawn_by, coverage);
  const run::DeviceRules rules = DeviceRulesOf(a, drawn_by);
  const run::ImageJudgement judgement = run::JudgeImage(scene, image, rules.rules, !a.no_map);
  std::optional<std::string> map;
  if (judgement.map) map = WriteMap(a, *judgement.map);
  const run_report::VerifyReport outputs{a.scene, a.image, scene.wireframe, drawn_by, rules, judgement, map};
  if (a.json)
    std::cout << run_report::VerifyJson(outputs).dump(2) << "\n";
  else
    ReportStream(a) << run_report::VerifyText(outputs);
  return ExitCodeOf(judgement.verdict);
}

}  // namespace

CommandRun AddVerifyCommand(CLI::App& app) {
  auto a = std::make_shared<VerifyArguments>();
  CLI::App* command =
      AddSubcommand(app, "verify", "judge any image of a scene by what a conformant Vulkan implementation may draw",
                    "Each pixel is certain (only one surface, or only the background, may show there),\n"
                    "uncertain (the spec lets more than one show) or a violation (no conformant\n"
                    "implementation may write that colour there). docs/verify.md lists the freedoms allowed.\n"
                    "The device's rules come from the options, else the image's PNG notes (render writes them),\n"
                    "else the spec's loosest (4 subpixel bits, non-strict lines), which the output then says.\n"
                    "Alpha is not judged: the output says how many pixels are not opaque.\n"
                    "Exit codes: 0 the image passes, 1 it has violations, 2 bad input or usage, 4 internal error,\n"
                    "6 inconclusive (no violation, but too little is certain to tell a broken image).\n"
                    "--coverage judges only where the image is covered, for engines with their own shading: each\n"
                    "pixel is the clear colour (background) or covered (any other R, G, B; alpha is not read).\n"
                    "Covered where no primitive may reach, or the clear colour where one certainly covers, is a\n"
                    "violation; edge pixels within the device's sub-pixel precision are free. Render with a clear\n"
                    "colour the shading never produces (docs/verify.md, \"Judging coverage only\").");
  command
      ->add_option("SCENE", a->scene,
                   "the scene file (JSON), OBJ mesh or glTF file the image is of, or - for\nstandard input")
      ->required();
  command->add_option("IMAGE.png", a->image, "the image to judge, at the scene's canvas size")->required();
  command->add_flag("--wireframe", a->wireframe, "the image draws triangle edges only, as render --wireframe does");
  ExpectIntegerIn(command
                      ->add_option("--subpixel-bits", a->subpixel_bits,
                                   "the device's subPixelPrecisionBits (default: the image's notes, else 4,\n"
                                   "the spec's minimum; lavapipe has 8, SwiftShader 4)")
                      ->type_name("N")
                      ->each([a](const std::string&) { a->bits_given = true; })
                      ->check(CLI::Validator(BelowSpecMinimum, "", "spec minimum")),
                  kMinSubpixelBits, 16);
  ExpectOneOf(command
                  ->add_option("--strict-lines", a->strict_lines,
                               "the device's strictLines (default: the image's notes, else false, which\n"
                               "allows every line rasterization)")
                  ->type_name("BOOL")
                  ->each([a](const std::string&) { a->strict_given = true; }),
              "value", {"true", "false"});
  command
      ->add_option("--map", a->map,
                   "write the verification map here (default: IMAGE-map.png); - writes it\n"
                   "to standard output, and the report to standard error")
      ->type_name("MAP.png");
  command->add_flag("--no-map", a->no_map, "write no map");
  AddSceneChoiceOptions(*command, a->choice);
  command->add_flag("--json", a->json,
                    "print one JSON object (twinraster.verify/3, with --coverage twinraster.verify-coverage/2;\n"
                    "docs/json-output.md)");
  command->add_flag("--coverage", a->coverage,
                    "judge only which pixels are covered, not their colours: for images from engines whose\n"
                    "shading twinraster does not model (glTF viewers, game engines)");
  command
      ->add_option("--background", a->background,
                   "with --coverage: the clear colour the engine used, as R,G,B or #rrggbb (default: the\n"
                   "scene's canvas background); any other colour reads as covered")
      ->type_name("COLOUR");
  command
      ->add_option("--hole-tolerance", a->hole_tolerance,
                   "with --coverage: pixels showing the clear colour where a primitive certainly covers that\n"
                   "are allowed, as a percentage of those pixels, for shading that can produce the clear\n"
                   "colour (default 0: none; better, a clear colour the shading never produces)")
      ->type_name("PERCENT");
  return [a] { return Verify(*a); };
}

}  // namespace twinraster::cli
