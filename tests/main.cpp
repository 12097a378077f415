// Catch2's runner, spelled so that Catch2 2 and 3 both accept it.
#define CATCH_CONFIG_RUNNER
#include "support/catch.hpp"

int main(int argc, char* argv[]) { return Catch::Session().run(argc, argv); }
