// The process's thread pool: every part runs exactly once, however many parts; an exception in a
// part reaches the caller after the others finish; a nested call runs inline instead of hanging.
#include "cpu/thread_pool.hpp"

#include "support/catch.hpp"

#include <atomic>
#include <stdexcept>
#include <vector>

using twinraster::cpu::RunParts;

TEST_CASE("RunParts runs every part exactly once, for any number of parts", "[cpu][pool]") {
  for (const unsigned parts : {0u, 1u, 2u, 3u, 8u, 33u}) {
    std::vector<std::atomic<int>> runs(parts);
    for (int round = 0; round < 50; ++round) RunParts(parts, [&](unsigned part) { ++runs[part]; });
    for (unsigned part = 0; part < parts; ++part) {
      INFO(parts << " parts, part " << part);
      REQUIRE(runs[part].load() == 50);
    }
  }
}

TEST_CASE("RunParts: a part's exception reaches the caller, and the pool still works", "[cpu][pool]") {
  std::atomic<int> finished{0};
  REQUIRE_THROWS_AS(RunParts(4,
                             [&](unsigned part) {
                               if (part == 2) throw std::runtime_error("part 2 failed");
                               ++finished;
                             }),
                    std::runtime_error);
  REQUIRE(finished.load() == 3);
  std::atomic<int> again{0};
  RunParts(4, [&](unsigned) { ++again; });
  REQUIRE(again.load() == 4);
}

TEST_CASE("RunParts inside a part runs inline", "[cpu][pool]") {
  std::atomic<int> inner{0};
  RunParts(3, [&](unsigned) { RunParts(5, [&](unsigned) { ++inner; }); });
  REQUIRE(inner.load() == 15);
}
