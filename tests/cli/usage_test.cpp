// Mistakes on the command line: one message saying what is wrong, exit code 2.
#include "support/test_support.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

using namespace twinraster;

TEST_CASE("Usage errors exit with 2 and say what is wrong", "[cli][usage]") {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{}, "missing command"},
      {{"frobnicate"}, "unknown command \"frobnicate\""},
      {{"explain"}, "missing SCENE"},
      {{"explain", "a.json", "b.json"}, "unexpected argument b.json"},
  };
  for (const auto& [args, message] : cases) {
    const test::CliResult r = test::RunCli(args);
    INFO(r.err);
    REQUIRE(r.exit_code == 2);
    REQUIRE(r.err.rfind("twinraster: " + message, 0) == 0);
  }
}
