// twinraster's command line: explain a scene's transform chain, render it on Vulkan and on the
// CPU twin, compare images. Every error becomes one message and an exit code.
#include "cli/commands.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/png_file.hpp"
#include "scene/scene_error.hpp"
#include "base/usage_error.hpp"

#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace twinraster;

constexpr const char* kUsage =
    "usage:\n"
    "  twinraster explain SCENE [--instance I] [--vertex V] [--json]\n"
    "      print the chapter's matrix chain for SCENE and trace its vertices to the framebuffer\n"
    "  twinraster render SCENE [-o OUT.png] [--backend gpu|cpu|both] [--json] [--device NAME] [--threads N]\n"
    "      draw SCENE on Vulkan (gpu), on the CPU twin (cpu), or both and compare them (default;\n"
    "      writes OUT-gpu.png, OUT-cpu.png, and OUT-diff.png when they differ; OUT defaults to\n"
    "      the scene's name in the current directory)\n"
    "  twinraster compare A.png B.png [--diff D.png] [--json]\n"
    "      count the pixels that differ between two images\n"
    "  twinraster bench [--out DIR] [--runs N] [--only TEXT] [--methods A,B] [--scenes DIR] [--json]\n"
    "      time every way of computing the chain and both renderers on the scene suite, against the\n"
    "      double-precision ground truth; with --out, also write bench.csv, .svg, .json, .txt\n"
    "exit codes: 0 done (images equal), 1 images differ, 2 bad input or usage, 3 no Vulkan device,\n"
    "  4 internal error\n";

int Run(const std::vector<std::string>& args) {
  if (args.empty()) throw UsageError("missing command");
  const std::string& command = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (command == "explain") return ExplainCommand(rest);
  if (command == "render") return RenderCommand(rest);
  if (command == "compare") return CompareCommand(rest);
  if (command == "bench") return BenchCommand(rest);
  if (command == "help" || command == "--help" || command == "-h") {
    std::cout << kUsage;
    return kExitOk;
  }
  throw UsageError("unknown command \"" + command + "\"");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const SceneError& e) {
    std::cerr << "twinraster: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const FileError& e) {
    std::cerr << "twinraster: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const GpuUnavailable& e) {
    std::cerr << "twinraster: no usable Vulkan device: " << e.what()
              << "\n  (render --backend cpu works without one)\n";
    return kExitNoVulkan;
  } catch (const UsageError& e) {
    std::cerr << "twinraster: " << e.what() << "\n" << kUsage;
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "twinraster: internal error: " << e.what() << "\n";
    return kExitInternalError;
  }
}
