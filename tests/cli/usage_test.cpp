// The command line itself: mistakes give one line saying what is wrong (with the closest valid
// command or option) and where to read more, exit code 2; --help and --version print on stdout.
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace twinraster;

TEST_CASE("Usage errors exit with 2, say what is wrong in one line, then where to look", "[cli][usage]") {
  const std::string scene = test::SourcePath("scenes/cgfs-scene.json").string();
  struct Case {
    std::vector<std::string> args;
    std::string message, hint;
  };
  const std::vector<Case> cases = {
      {{"frobnicate"}, "twinraster: unknown command \"frobnicate\"", "see 'twinraster --help'"},
      {{"rendr", scene}, "twinraster: unknown command \"rendr\" (did you mean \"render\"?)", "see 'twinraster --help'"},
      {{"--frobnicate"}, "twinraster: unknown option --frobnicate", "see 'twinraster --help'"},
      {{"--verison"}, "twinraster: unknown option --verison (did you mean --version?)", "see 'twinraster --help'"},
      {{"explain"}, "twinraster explain: missing SCENE", "see 'twinraster explain --help'"},
      {{"explain", "a.json", "b.json"},
       "twinraster explain: unexpected argument b.json",
       "see 'twinraster explain --help'"},
      {{"compare", "a.png"}, "twinraster compare: missing B.png", "see 'twinraster compare --help'"},
      {{"render", scene, "--backnd", "gpu"},
       "twinraster render: unknown option --backnd (did you mean --backend?)",
       "see 'twinraster render --help'"},
      {{"render", scene, "--jsno=1"},
       "twinraster render: unknown option --jsno (did you mean --json?)",
       "see 'twinraster render --help'"},
      {{"render", scene, "--backend", "gpuu"},
       "twinraster render: --backend: unknown backend \"gpuu\" (did you mean \"gpu\"?); choose from gpu, cpu, both",
       "see 'twinraster render --help'"},
      {{"render", scene, "--threads"},
       "twinraster render: option --threads needs a value",
       "see 'twinraster render --help'"},
      {{"render", scene, "--rules", "book", "--backend", "gpu"},
       "twinraster render: --rules book draws on the CPU only, as the chapter's demos do: drop --backend gpu",
       "see 'twinraster render --help'"},
      {{"render", scene, "--backend", "both", "--rules", "book"},
       "twinraster render: --rules book draws on the CPU only, as the chapter's demos do: drop --backend both",
       "see 'twinraster render --help'"},
      {{"render", scene, "--rules", "bok"},
       "twinraster render: --rules: unknown rule set \"bok\" (did you mean \"book\"?); choose from vulkan, book",
       "see 'twinraster render --help'"},
      {{"render", scene, "--json=maybe"},
       "twinraster render: --json: cannot take the value \"maybe\"",
       "see 'twinraster render --help'"},
      {{"explain", scene, "--vertex", "x"},
       "twinraster explain: --vertex: expects a non-negative integer, got \"x\"",
       "see 'twinraster explain --help'"},
      {{"explain", scene, "compare"},
       "twinraster explain: unexpected argument compare",
       "see 'twinraster explain --help'"},
      {{"render", scene, "--png-level", "13"},
       "twinraster render: --png-level: expects an integer in 0..12, got \"13\"",
       "see 'twinraster render --help'"},
      {{"render", scene, scene},
       "twinraster render: two scenes are named \"cgfs-scene\": their images would overwrite each other; render them "
       "in separate calls",
       "see 'twinraster render --help'"},
      // Never CLI11's "Value -1 not in range 0.000000 to 1797...", and never nan or inf let through.
      {{"render", scene, "--timeout", "-1"},
       "twinraster render: --timeout: expects seconds from 0 (no limit) to 1000000, got \"-1\"",
       "see 'twinraster render --help'"},
      {{"render", scene, "--timeout", "abc"},
       "twinraster render: --timeout: expects seconds from 0 (no limit) to 1000000, got \"abc\"",
       "see 'twinraster render --help'"},
      {{"render", scene, "--timeout", "inf"},
       "twinraster render: --timeout: expects seconds from 0 (no limit) to 1000000, got \"inf\"",
       "see 'twinraster render --help'"},
      {{"render", scene, "--timeout=nan"},
       "twinraster render: --timeout: expects seconds from 0 (no limit) to 1000000, got \"nan\"",
       "see 'twinraster render --help'"},
      {{"render", scene, "--timeout", "1e7"},
       "twinraster render: --timeout: expects seconds from 0 (no limit) to 1000000, got \"1e7\"",
       "see 'twinraster render --help'"},
      // An image is read from a file only: - is refused, never opened as a file named "-".
      {{"verify", scene, "-"},
       "twinraster verify: IMAGE.png -: images are read from files, not from standard input; write it to a file "
       "first (render -o FILE.png)",
       "see 'twinraster verify --help'"},
      {{"compare", "a.png", "-"},
       "twinraster compare: B.png -: images are read from files, not from standard input; write it to a file first "
       "(render -o FILE.png)",
       "see 'twinraster compare --help'"},
      {{"bench", "--runs", "0"},
       "twinraster bench: --runs: expects an integer in 1..1000, got \"0\"",
       "see 'twinraster bench --help'"},
      {{"help", "rendr"},
       "twinraster help: unknown command \"rendr\" (did you mean \"render\"?)",
       "see 'twinraster help --help'"},
  };
  for (const Case& c : cases) {
    const test::CliResult r = test::RunCli(c.args);
    INFO(r.err);
    REQUIRE(r.exit_code == 2);
    REQUIRE(r.out.empty());
    REQUIRE(r.err == c.message + "\n" + c.hint + "\n");
  }
}

TEST_CASE("A bare twinraster prints the usage, on standard error, and exits 2", "[cli][usage]") {
  const test::CliResult r = test::RunCli({});
  INFO(r.err);
  REQUIRE(r.exit_code == 2);
  REQUIRE(r.out.empty());
  REQUIRE(r.err.find("missing command") == std::string::npos);
  REQUIRE(r.err.find("Usage: twinraster [OPTIONS] [COMMAND]\n") != std::string::npos);
  for (const char* command : {"explain", "render", "verify", "compare", "bench", "Exit codes"}) {
    INFO(command);
    REQUIRE(r.err.find(command) != std::string::npos);
  }
}

TEST_CASE("render --timeout takes a fraction of a second, and 0 for no limit", "[cli][usage]") {
  const test::TempDir dir;
  const std::string scene = test::SourcePath("scenes/cgfs-scene.json").string();
  for (const char* seconds : {"0", "0.5e3", "1000000"}) {
    INFO(seconds);
    const test::CliResult r =
        test::RunCli({"render", scene, "--backend", "cpu", "--timeout", seconds, "-o", (dir / "t.png").string(), "-q"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
  }
}

TEST_CASE("Help: --help, -h and the help command print a command's usage on stdout and exit 0", "[cli][usage]") {
  struct Case {
    std::vector<std::string> args;
    std::string usage;
    std::vector<std::string> mentions;
  };
  const std::vector<Case> cases = {
      {{"--help"},
       "Usage: twinraster [OPTIONS] [COMMAND]",
       {"explain", "render", "compare", "bench", "--version", "Exit codes"}},
      {{"-h"}, "Usage: twinraster [OPTIONS] [COMMAND]", {"explain", "render", "compare", "bench"}},
      {{"help"}, "Usage: twinraster [OPTIONS] [COMMAND]", {"explain", "render", "compare", "bench"}},
      {{"render", "--help"},
       "Usage: twinraster render [OPTIONS] SCENE...",
       {"-o,--output OUT.png|DIR", "--png-level 0-12", "--backend gpu|cpu|both", "--rules vulkan|book", "--json",
        "--device NAME", "--threads N", "-q,--quiet", "standard input", "standard output"}},
      {{"render", "-h", "no-such-scene.json", "--backend", "cpu"},
       "Usage: twinraster render [OPTIONS] SCENE...",
       {"--backend"}},
      {{"help", "render"}, "Usage: twinraster render [OPTIONS] SCENE...", {"--backend"}},
      {{"explain", "--help"}, "Usage: twinraster explain [OPTIONS] SCENE", {"--instance I", "--vertex V", "--json"}},
      {{"compare", "-h"}, "Usage: twinraster compare [OPTIONS] A.png B.png", {"--diff D.png", "--json"}},
      {{"bench", "--help"},
       "Usage: twinraster bench [OPTIONS]",
       {"--out DIR", "--runs N", "--only TEXT", "--methods A,B", "--scenes DIR", "--json", "-q,--quiet", "lavapipe"}},
  };
  for (const Case& c : cases) {
    const test::CliResult r = test::RunCli(c.args);
    INFO(c.usage);
    INFO(r.out + r.err);
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.err.empty());
    REQUIRE(r.out.find(c.usage + "\n") != std::string::npos);
    for (const std::string& mention : c.mentions) {
      INFO(mention);
      REQUIRE(r.out.find(mention) != std::string::npos);
    }
  }
}

TEST_CASE("Version: --version prints the project version, and in a git checkout the commit", "[cli][usage]") {
  const test::CliResult r = test::RunCli({"--version"});
  INFO(r.out + r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.err.empty());
  const std::string version = std::string("twinraster ") + TWINRASTER_VERSION;
  REQUIRE(r.out.rfind(version, 0) == 0);
  const std::string first_line = r.out.substr(0, r.out.find('\n') + 1);
  if (std::filesystem::exists(test::SourcePath(".git"))) {
    // git describe --always: a tag or an abbreviated commit, "-dirty" when tracked files changed.
    REQUIRE(std::regex_match(first_line, std::regex(version + R"( \([0-9A-Za-z._/-]+\)\n)")));
  } else {
    REQUIRE(first_line == version + "\n");
  }
  // Then the CPU path lavapipe takes here and the lavapipes the twin copies bit for bit.
  REQUIRE(r.out.find("\nlavapipe's CPU path on this machine: ") != std::string::npos);
  const std::size_t rules =
      r.out.find("\nthe twin has bit-exact rules for:\n  Mesa 22.3.6 (LLVM 15), AVX2+FMA, 256-bit: ");
  REQUIRE(rules != std::string::npos);
  // Each row names the CI step that proves it against its driver (docs/lavapipe-paths.md).
  std::istringstream rows(r.out.substr(r.out.find('\n', rules + 1) + 1));
  int rows_read = 0;
  for (std::string row; std::getline(rows, row) && row.starts_with("  Mesa ");) {
    INFO(row);
    CHECK(row.find(": proven in CI by ") != std::string::npos);
    ++rows_read;
  }
  CHECK(rows_read >= 9);
  // Every command answers --version the same way, without its required arguments.
  for (const char* command : {"explain", "render", "compare", "bench", "help"}) {
    INFO(command);
    const test::CliResult c = test::RunCli({command, "--version"});
    REQUIRE(c.exit_code == 0);
    REQUIRE(c.out == r.out);
  }
}
