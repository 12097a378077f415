// Catch2's runner, spelled so that Catch2 2 and 3 both accept it.
#define CATCH_CONFIG_RUNNER
#include "support/catch.hpp"
#include "support/test_support.hpp"

int main(int argc, char* argv[]) {
  const int result = Catch::Session().run(argc, argv);
  twinraster::test::RunEndOfRunWork();
  // Catch2 2 returns the number of failed assertions: never let a failure read as "skipped".
  return result == twinraster::test::kSkippedExitCode ? 1 : result;
}
