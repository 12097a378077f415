// `twinraster render SCENE...`: its options, and the loop over the scenes. Each scene is read and
// drawn (render_scene.hpp; run/run_scene.hpp runs it), its files written (render_files.hpp) and its
// record printed (render_printing.hpp), one scene after another or as a batch (render_batch.hpp);
// the batch's page, JUnit file and exit code read its one result (run/batch_result.hpp). Several
// scenes share one GPU process and write into one directory.
#include "base/stopwatch.hpp"
#include "cli/commands.hpp"
#include "cli/parser_setup.hpp"
#include "cli/render_arguments.hpp"
#include "cli/render_batch.hpp"
#include "cli/render_files.hpp"
#include "cli/render_option_checks.hpp"
#include "cli/scene_choice_options.hpp"
#include "cpu/cpu_renderer.hpp"
#include "run/batch_result.hpp"
#include "run/run_scene.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

namespace twinraster::cli {

namespace {

// About 11.6 days: any scene's limit, and a wait in milliseconds that fits an int.
constexpr int kMaxTimeoutSeconds = 1'000'000;

int Render(RenderArguments& a) {
  ResolveOptions(a);
  CheckOutput(a);
  PrepareDestinations(a);
  Progress progress = Progress::OnStandardError(a.quiet);
  RenderBatch batch(a, progress);  // several scenes: each written while the next draws
  gpu::IsolationOptions isolation;
  isolation.gpu.device = a.device;
  isolation.timeout_seconds = a.timeout_seconds;
  isolation.before_fork = batch.BeforeFork();
  run::GpuSession gpu(isolation);  // a child process, made for the first GPU draw and kept
  // The exit code is the worst verdict's (run/batch_result.hpp). No Vulkan device ends the run (exit 3).
  Stopwatch batch_clock;
  for (const std::string& scene : a.scenes) batch.Render(scene, gpu);
  run::BatchResult result = batch.Finish();
  result.total_ms = batch_clock.Milliseconds();
  WriteBatchReports(a, result);
  return result.ExitCode();
}

}  // namespace

CommandRun AddRenderCommand(CLI::App& app) {
  auto a = std::make_shared<RenderArguments>();
  CLI::App* command = AddSubcommand(
      app, "render", "draw a scene on Vulkan, on the CPU twin, or on both and compare; or as the book's demos do",
      "Each PNG is written whole to a temporary file and renamed into place: a failed run leaves\n"
      "earlier files untouched, and a read-only file is never replaced. Every output is checked\n"
      "before anything is drawn. On a terminal, progress shows on standard error.\n"
      "The Vulkan work runs in a child process: when the driver crashes or passes --timeout, the\n"
      "report says so, the twin's image is still written, and later scenes still render.\n"
      "Exit codes: 0 done (both: identical images, or different where the twin has no rules for\n"
      "the driver and the verifier passes the GPU's), 1 the images differ (or --verify found a\n"
      "violation), 2 bad input or usage,\n"
      "3 no usable Vulkan device (--backend cpu needs none), 4 internal error, 5 the Vulkan\n"
      "driver crashed or timed out (the twin's image and the report were still written), 6 the\n"
      "verifier found no violation but could not tell a broken image (inconclusive).");
  command
      ->add_option("SCENE", a->scenes,
                   "scene files (JSON), OBJ meshes (.obj: framed, lit by a headlight), glTF 2.0\n"
                   "files (.gltf, .glb: their camera, or framed), or - to read one scene from\n"
                   "standard input")
      ->required();
  command
      ->add_option("-o,--output", a->output,
                   "gpu, cpu: write OUT.png; both: OUT-gpu.png, OUT-cpu.png and, when\n"
                   "they differ, OUT-diff.png. Default: the scene's name in the current\n"
                   "directory. - writes the PNG to standard output (gpu or cpu only).\n"
                   "DIR/ (a final /) or an existing directory, and with several scenes any\n"
                   "name but OUT.png (default .): each scene's files go there, named after it.\n"
                   "Missing directories are made, for every option that writes")
      ->type_name("OUT.png|DIR");
  ExpectIntegerIn(command
                      ->add_option("--png-level", a->png_level,
                                   "PNG compression, 0 (none) to 12 (smallest, slowest); default 1, the fastest")
                      ->type_name("0-12"),
                  0, 12);
  CLI::Option* backend =
      ExpectOneOf(command->add_option("--backend", a->backend, "where to draw (default: both; with --rules book, cpu)")
                      ->type_name("gpu|cpu|both"),
                  "backend", {"gpu", "cpu", "both"});
  ExpectOneOf(command
                  ->add_option("--rules", a->rules,
                               "vulkan (default): filled triangles, depth-tested and clipped, by Vulkan's\n"
                               "rules. book: wireframes drawn as the chapter's live demos draw them\n"
                               "(truncated coordinates, no clipping, no depth), on the CPU only")
                  ->type_name("vulkan|book"),
              "rule set", {"vulkan", "book"});
  command->add_flag("--wireframe", a->wireframe,
                    "draw triangle edges only (Vulkan's polygonMode LINE, 1 pixel, depth-tested), as\n"
                    "if the scene said \"wireframe\": true; the twin follows the device's line rules");
  command->add_flag("--verify", a->verify,
                    "judge the image drawn (the GPU's, if drawn) by what a conformant Vulkan\n"
                    "implementation may draw, pixel by pixel (docs/verify.md), and write its\n"
                    "map beside it as OUT-map.png (OUT-gpu-map.png with both); exit 1 on a\n"
                    "violation. Without it, a difference between the two images is still judged");
  command->add_flag("--json", a->json, "print the report as JSON (twinraster.render/5, docs/json-output.md)");
  command
      ->add_option("--device", a->device,
                   "the Vulkan device to draw on, whose rules the twin follows: lavapipe (default),\n"
                   "swiftshader, or any part of a device's full name, in any case (--version lists\n"
                   "them). --backend cpu opens none: the name alone chooses the twin's rules, and\n"
                   "one it has none for is refused")
      ->type_name("NAME");
  // The bound keeps the GPU process's wait, in milliseconds, inside an int (poll's timeout).
  ExpectNumberIn(command
                     ->add_option("--timeout", a->timeout_seconds,
                                  "seconds the Vulkan driver may take for one scene before it is stopped and\n"
                                  "the scene reported as timed out (default 600; 0: no limit; at most 1000000)")
                     ->type_name("SECONDS"),
                 0, kMaxTimeoutSeconds, "seconds from 0 (no limit) to " + std::to_string(kMaxTimeoutSeconds));
  ExpectIndex(command
                  ->add_option("--threads", a->threads,
                               "the CPU twin's threads, at most one per 16 rows (default: every core for a\n"
                               "frame of over " +
                                   std::to_string(cpu::kOneThreadPixels) + " pixels or over " +
                                   std::to_string(cpu::kOneThreadTriangles) +
                                   " triangles, counting every\n"
                                   "instance's; one for a smaller frame, where another costs more than it saves)")
                  ->type_name("N"));
  AddSceneChoiceOptions(*command, a->choice);
  command->add_flag("-q,--quiet", a->quiet, "no progress on standard error (and, with -o -, no report)");
  command
      ->add_option("--report", a->report,
                   "also write DIR/index.html: one page for the batch, failures first, each scene's\n"
                   "images as thumbnails (DIR/thumbs/) with its verdict, counts, device and times;\n"
                   "every verification's map is written too")
      ->type_name("DIR");
  command
      ->add_option("--junit", a->junit,
                   "also write the batch as JUnit XML (one testcase per scene) to FILE; - writes it\n"
                   "to standard output, and the report to standard error")
      ->type_name("FILE");
  return [a, backend] {
    a->backend_given = backend->count() > 0;
    return Render(*a);
  };
}

}  // namespace twinraster::cli
