// Output paths as a user meets them (docs/commands.md, "Output paths"): every destination is
// checked before any drawing, missing directories are made for every option that writes, - is a
// standard stream wherever it is accepted, and a read-only file is never replaced. CI runs as
// root, whom the system lets write anything: a file is read-only here by its mode bits alone.
#include "files/png_file.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

const std::string kScene = test::SourcePath("scenes/cgfs-transforms.json").string();
const std::string kLookAt = test::SourcePath("scenes/lookat.json").string();

void MakeReadOnly(const std::filesystem::path& file, const std::string& text) {
  test::WriteFile(file, text);
  std::filesystem::permissions(file, std::filesystem::perms(0444));
}

std::filesystem::perms Mode(const std::filesystem::path& file) {
  return std::filesystem::status(file).permissions() & std::filesystem::perms::all;
}

std::size_t Entries(const std::filesystem::path& dir) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

}  // namespace

TEST_CASE("render never replaces a read-only output, naming it, and leaves its bytes and mode alone",
          "[cli][render][outputs]") {
  const test::TempDir dir;
  const auto golden = dir / "golden.png";
  MakeReadOnly(golden, "protected golden image");
  const test::CliResult r = test::RunCli({"render", kScene, "-o", golden.string(), "--backend", "cpu"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.err ==
        "twinraster: -o " + golden.string() + ": is read-only, so it is not replaced (chmod u+w to allow it)\n");
  CHECK(r.out.empty());  // refused before the scene was read
  CHECK(test::ReadFile(golden) == "protected golden image");
  CHECK(Mode(golden) == std::filesystem::perms(0444));
  CHECK(Entries(dir.path()) == 1);

  // One of the files -o OUT.png stands for (both backends: OUT-gpu.png, OUT-cpu.png, OUT-diff.png).
  MakeReadOnly(dir / "x-diff.png", "earlier diff");
  const test::CliResult both = test::RunCli({"render", kScene, "-o", (dir / "x.png").string()});
  CHECK(both.exit_code == 2);
  CHECK_THAT(both.err,
             HasSubstring("-o " + (dir / "x.png").string() + ": " + (dir / "x-diff.png").string() + ": is read-only"));
  CHECK_FALSE(std::filesystem::exists(dir / "x-gpu.png"));
}

TEST_CASE("An unwritable destination fails before the GPU is started, not after --timeout or the batch",
          "[cli][render][outputs][isolation]") {
  // The fake driver hangs until --timeout: any drawing would take 60 s and exit 5.
  const std::vector<std::string> hang = {"TWINRASTER_TEST_GPU_FAULT=hang"};
  const test::TempDir dir;
  MakeReadOnly(dir / "golden.png", "protected");
  test::WriteFile(dir / "plain", "a file where a directory should be");
  const std::vector<std::vector<std::string>> runs = {
      {"render", kScene, "-o", (dir / "golden.png").string(), "--backend", "gpu", "--timeout", "60"},
      {"render", kScene, "-o", (dir / "plain" / "x.png").string(), "--timeout", "60"},
      {"render", kScene, kLookAt, "-o", (dir / "out").string(), "--junit", (dir / "plain" / "j.xml").string(),
       "--timeout", "60"},
      {"render", kScene, kLookAt, "-o", (dir / "out").string(), "--report", (dir / "plain" / "r").string(), "--timeout",
       "60"},
  };
  for (const auto& run : runs) {
    INFO(run[run.size() - 3] << " " << run[run.size() - 2]);
    const auto start = std::chrono::steady_clock::now();
    const test::CliResult r = test::RunCli(run, hang);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO(r.out << r.err);
    CHECK(r.exit_code == 2);
    CHECK(seconds < 30);
    CHECK(r.out.empty());
    CHECK(r.err.find("timed out") == std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "out"));  // nothing made: the checks all pass or none act
  }
}

TEST_CASE("Missing directories are made for every option that writes, and a file in the way is named",
          "[cli][outputs]") {
  const test::TempDir dir;
  const std::string png = (dir / "in.png").string();
  REQUIRE(test::RunCli({"render", kScene, "-o", png, "--backend", "cpu", "-q"}).exit_code == 0);
  Image other = files::ReadPng(png);
  other.rgba[0] = static_cast<std::uint8_t>(other.rgba[0] + 1);
  files::WritePng(dir / "other.png", other);

  const auto render =
      test::RunCli({"render", kScene, "-o", (dir / "ci" / "ll.png").string(), "--backend", "cpu", "--junit",
                    (dir / "j" / "k" / "j.xml").string(), "--report", (dir / "r" / "s").string()});
  INFO(render.err);
  CHECK(render.exit_code == 0);
  CHECK(files::ReadPng(dir / "ci" / "ll.png").width == 600);
  CHECK(std::filesystem::is_regular_file(dir / "j" / "k" / "j.xml"));
  CHECK(std::filesystem::is_regular_file(dir / "r" / "s" / "index.html"));
  CHECK(test::RunCli({"explain", kScene, "--html", (dir / "e" / "x.html").string()}).exit_code == 0);
  CHECK(std::filesystem::is_regular_file(dir / "e" / "x.html"));
  CHECK(test::RunCli({"verify", kScene, png, "--map", (dir / "m" / "m.png").string()}).exit_code == 0);
  CHECK(files::ReadPng(dir / "m" / "m.png").width == 600);
  CHECK(test::RunCli({"compare", png, (dir / "other.png").string(), "--diff", (dir / "d" / "d.png").string()})
            .exit_code == 1);
  CHECK(files::ReadPng(dir / "d" / "d.png").width == 600);

  // A file where a directory must go: one line naming the option and the file, exit 2, nothing made.
  test::WriteFile(dir / "plain", "x");
  const std::string in_file = (dir / "plain" / "sub" / "f").string();
  const std::vector<std::vector<std::string>> refused = {
      {"render", kScene, "--backend", "cpu", "-o", in_file + ".png"},
      {"render", kScene, "--backend", "cpu", "-o", png, "--junit", in_file + ".xml"},
      {"render", kScene, "--backend", "cpu", "-o", png, "--report", in_file},
      {"explain", kScene, "--html", in_file + ".html"},
      {"verify", kScene, png, "--map", in_file + ".png"},
      {"compare", png, png, "--diff", in_file + ".png"},
      {"bench", "--out", in_file},
      {"bench", "--html", in_file + ".html"},
      {"bench", "--svg", in_file + ".svg"},
  };
  for (const auto& run : refused) {
    const std::string option = run[run.size() - 2] + " " + run.back();
    INFO(option);
    const test::CliResult r = test::RunCli(run);
    CHECK(r.exit_code == 2);
    CHECK(r.err == "twinraster: " + option + ": " + (dir / "plain").string() + " is a file, not a directory\n");
    CHECK(r.out.empty());
  }
}

TEST_CASE("render -o names a directory by a final / or an existing one, and a PNG name for several scenes is refused",
          "[cli][render][outputs]") {
  const test::TempDir dir;
  const test::CliResult one = test::RunCli({"render", kScene, "-o", (dir / "ci").string() + "/", "--backend", "cpu"});
  INFO(one.err);
  CHECK(one.exit_code == 0);
  CHECK(files::ReadPng(dir / "ci" / "cgfs-transforms.png").width == 600);
  CHECK(test::RunCli({"render", kLookAt, "-o", (dir / "ci").string(), "--backend", "cpu"}).exit_code == 0);
  CHECK(files::ReadPng(dir / "ci" / "lookat.png").width == 640);

  const test::CliResult multi = test::RunCli({"render", kScene, kLookAt, "-o", (dir / "multi.png").string()});
  CHECK(multi.exit_code == 2);
  CHECK_THAT(multi.err, HasSubstring("several scenes are written into a directory, and this names a PNG"));
  CHECK_FALSE(std::filesystem::exists(dir / "multi.png"));
  // Said with a final /, a directory of that name is what was meant.
  CHECK(test::RunCli({"render", kScene, kLookAt, "-o", (dir / "multi.png").string() + "/", "--backend", "cpu"})
            .exit_code == 0);
  CHECK(std::filesystem::is_regular_file(dir / "multi.png" / "lookat.png"));
  // Standard input has no name to give its files.
  CHECK(test::RunCliWithInput({"render", "-", "-o", (dir / "ci").string() + "/", "--backend", "cpu"},
                              test::ReadFile(kScene))
            .exit_code == 2);
}

TEST_CASE("A - output is standard output for every option that writes one file, and refused for a directory",
          "[cli][outputs]") {
  const test::TempDir dir;
  const std::string png = (dir / "in.png").string();
  REQUIRE(test::RunCli({"render", kScene, "-o", png, "--backend", "cpu", "-q"}).exit_code == 0);
  const std::filesystem::path cwd = std::filesystem::current_path();

  const test::CliResult junit = test::RunCli({"render", kScene, "-o", png, "--backend", "cpu", "--junit", "-"});
  INFO(junit.err);
  CHECK(junit.exit_code == 0);
  CHECK(junit.out.rfind("<?xml", 0) == 0);
  CHECK_THAT(junit.err, HasSubstring("cpu: " + png));  // the report moves to standard error

  const test::CliResult page = test::RunCli({"explain", kScene, "--html", "-"});
  CHECK(page.exit_code == 0);
  CHECK(page.out.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(page.out.find("wrote -") == std::string::npos);

  const test::CliResult map = test::RunCli({"verify", kScene, png, "--map", "-"});
  CHECK(map.exit_code == 0);
  CHECK(files::DecodePng(map.out, "standard output").width == 600);
  CHECK_THAT(map.err, HasSubstring("map: standard output"));

  Image other = files::ReadPng(png);
  other.rgba[0] = static_cast<std::uint8_t>(other.rgba[0] + 1);
  files::WritePng(dir / "other.png", other);
  const test::CliResult diff = test::RunCli({"compare", png, (dir / "other.png").string(), "--diff", "-"});
  CHECK(diff.exit_code == 1);
  CHECK(files::DecodePng(diff.out, "standard output").width == 600);
  CHECK_THAT(diff.err, HasSubstring("diff in standard output"));
  CHECK_FALSE(std::filesystem::exists(cwd / "-"));  // never a file named -

  // Two things for standard output, or a stream for a directory: refused before any work.
  for (const auto& run : std::vector<std::vector<std::string>>{
           {"render", kScene, "-o", png, "--junit", "-", "--json"},
           {"render", kScene, "-o", "-", "--backend", "cpu", "--junit", "-"},
           {"render", kScene, "-o", png, "--report", "-"},
           {"explain", kScene, "--html", "-", "--json"},
           {"verify", kScene, png, "--map", "-", "--json"},
           {"compare", png, png, "--diff", "-", "--json"},
           {"bench", "--out", "-"},
           {"bench", "--html", "-", "--svg", "-"},
       }) {
    INFO(run[1] << " " << run[run.size() - 2] << " " << run.back());
    const test::CliResult r = test::RunCli(run);
    CHECK(r.exit_code == 2);
    CHECK(r.out.empty());
  }
}

TEST_CASE("verify checks its map beside the image before judging, and leaves a read-only one alone",
          "[cli][verify][outputs]") {
  const test::TempDir dir;
  const std::string png = (dir / "in.png").string();
  REQUIRE(test::RunCli({"render", kScene, "-o", png, "--backend", "cpu", "-q"}).exit_code == 0);
  MakeReadOnly(dir / "in-map.png", "earlier map");
  const test::CliResult r = test::RunCli({"verify", kScene, png});
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, HasSubstring("--map MAP.png or --no-map"));
  CHECK(r.out.empty());
  CHECK(test::ReadFile(dir / "in-map.png") == "earlier map");
  CHECK(test::RunCli({"verify", kScene, png, "--no-map"}).exit_code == 0);
  CHECK(test::RunCli({"verify", kScene, png, "--no-map", "--map", (dir / "m.jpg").string()}).exit_code == 2);
  MakeReadOnly(dir / "d.png", "earlier diff");
  CHECK(test::RunCli({"compare", png, png, "--diff", (dir / "d.png").string()}).exit_code == 2);
  CHECK(test::ReadFile(dir / "d.png") == "earlier diff");  // not removed as stale either
}
