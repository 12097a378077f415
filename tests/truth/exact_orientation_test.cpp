// The edge function's sign is exact: right where plain double arithmetic gets it wrong, and the
// same (negated) for both directions of an edge, which makes shared edges watertight.
#include "truth/exact_orientation.hpp"

#include "support/catch.hpp"

#include <cmath>
#include <random>

using namespace twinraster::truth;

TEST_CASE("Edge function: simple values and the twin's sign convention", "[truth][exact]") {
  // E(v0, v1, v2) is twice the signed area; (0,0), (0,4), (4,0) is positive in the twin's convention.
  CHECK(EvaluateEdge({0, 0}, {0, 4}, {4, 0}).sign == 1);
  CHECK(EvaluateEdge({0, 0}, {0, 4}, {4, 0}).value == 16.0);
  CHECK(EvaluateEdge({0, 0}, {4, 0}, {0, 4}).sign == -1);
  CHECK(EvaluateEdge({0, 0}, {0, 4}, {0, 2}).sign == 0);  // on the edge
  CHECK(EvaluateEdge({0, 0}, {0, 4}, {0, 9}).sign == 0);  // on the edge's line
  CHECK(EvaluateEdge({1, 1}, {1, 1}, {3, 7}).sign == 0);  // degenerate edge
}

TEST_CASE("Edge function: exact sign near a line where plain double arithmetic fails", "[truth][exact]") {
  // Kettner et al., "Classroom examples of robustness problems": p = (0.5 + i·u, 0.5 + j·u),
  // u = 2^-53, against the line through (12, 12) and (24, 24). Exactly, E = 12 · (p.x - p.y),
  // so the sign is that of i - j.
  const glm::dvec2 a{12, 12}, b{24, 24};
  const double u = std::ldexp(1.0, -53);
  int plain_wrong = 0;
  for (int i = 0; i < 32; ++i) {
    for (int j = 0; j < 32; ++j) {
      const glm::dvec2 p{0.5 + i * u, 0.5 + j * u};
      const int expected = (i > j) - (i < j);
      INFO("i = " << i << ", j = " << j);
      REQUIRE(EvaluateEdge(a, b, p).sign == expected);
      REQUIRE(EvaluateEdgeExactly(a, b, p).sign == expected);
      REQUIRE(EvaluateEdge(b, a, p).sign == -expected);
      const double plain = (a.y - b.y) * (a.x - p.x) - (a.x - b.x) * (a.y - p.y);
      plain_wrong += ((plain > 0) - (plain < 0)) != expected ? 1 : 0;
    }
  }
  CHECK(plain_wrong > 0);  // the case really needs exact arithmetic
}

TEST_CASE("Edge function: fast path and exact path agree, and reversing the edge negates", "[truth][exact]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(0.0, 600.0), tiny(-1e-12, 1e-12);
  for (int n = 0; n < 20000; ++n) {
    const glm::dvec2 a{coord(rng), coord(rng)}, b{coord(rng), coord(rng)};
    // Points on or extremely close to the edge's line, where rounding decides.
    const double t = std::uniform_real_distribution<double>(-0.5, 1.5)(rng);
    const glm::dvec2 p = a + t * (b - a) + glm::dvec2{tiny(rng), tiny(rng)};
    const EdgeValue fast = EvaluateEdge(a, b, p), exact = EvaluateEdgeExactly(a, b, p);
    REQUIRE(fast.sign == exact.sign);
    REQUIRE(EvaluateEdge(b, a, p).sign == -exact.sign);
    REQUIRE(((exact.value > 0) - (exact.value < 0)) == exact.sign);
  }
}
