// `twinraster compare A.png B.png`: counts differing pixels, optionally writing a diff image.
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/comparison_report.hpp"
#include "image/image_compare.hpp"
#include "image/png_file.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

namespace twinraster {

int CompareCommand(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--json"}, {"--diff"});
  cl.ExpectPositional({"A.png", "B.png"});
  const Image a = ReadPng(cl.Positional()[0]);
  const Image b = ReadPng(cl.Positional()[1]);
  const Comparison comparison = CompareImages(a, b);
  const std::optional<std::string> diff = cl.Option("--diff");
  const bool wrote_diff = diff && comparison.same_size && !comparison.Equal();
  if (wrote_diff) WritePng(*diff, DiffImage(a, b));
  // A diff left by an earlier run would now describe images that no longer differ.
  std::error_code ignored;
  if (diff && comparison.Equal() && std::filesystem::is_regular_file(*diff, ignored)) {
    std::filesystem::remove(*diff, ignored);
  }

  if (cl.Flag("--json")) {
    nlohmann::ordered_json out = ComparisonJson(a, b, comparison);
    out["diff"] = wrote_diff ? nlohmann::ordered_json(*diff) : nlohmann::ordered_json(nullptr);
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << ComparisonText(a, b, comparison) << (wrote_diff ? ", diff in " + *diff : "") << "\n";
  }
  return comparison.Equal() ? kExitOk : kExitImagesDiffer;
}

}  // namespace twinraster
