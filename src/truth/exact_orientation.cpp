#include "truth/exact_orientation.hpp"

#include <cmath>

namespace twinraster::truth {

namespace {

// Half an ulp of 1: the relative error of one rounded operation.
constexpr double kEpsilon = 0x1p-53;

// Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates"
// (1997), orient2d's first stage: the plainly computed determinant L - R has the exact sign when
// its magnitude exceeds this times |L| + |R|.
constexpr double kPlainErrorBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;

struct TwoDoubles {
  double hi, lo;  // hi + lo is the exact result
};

TwoDoubles TwoProduct(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};  // an explicit fma: the one place a fused rounding is wanted
}

// Knuth's branch-free exact addition.
TwoDoubles TwoSum(double a, double b) {
  const double s = a + b;
  const double b_part = s - a;
  const double a_part = s - b_part;
  return {s, (a - a_part) + (b - b_part)};
}

// e[0 .. n) is a nonoverlapping expansion (exact sum of its components, ordered by increasing
// magnitude, zeros allowed); adds x to it without error (Shewchuk's Grow-Expansion). Returns n + 1.
int GrowExpansion(double* e, int n, double x) {
  for (int i = 0; i < n; ++i) {
    const TwoDoubles s = TwoSum(x, e[i]);
    e[i] = s.lo;
    x = s.hi;
  }
  e[n] = x;
  return n + 1;
}

int Sign(double v) { return (v > 0) - (v < 0); }

}  // namespace

EdgeValue EvaluateEdgeExactly(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  // Expanded, E = (a.x p.y - a.y p.x) + (p.x b.y - p.y b.x) + (b.x a.y - b.y a.x): six products
  // of input coordinates, each split exactly into two doubles, then summed exactly.
  const TwoDoubles products[6] = {TwoProduct(a.x, p.y),  TwoProduct(-a.y, p.x), TwoProduct(p.x, b.y),
                                  TwoProduct(-p.y, b.x), TwoProduct(b.x, a.y),  TwoProduct(-b.y, a.x)};
  double e[12];
  int n = 0;
  for (const TwoDoubles& q : products) {
    n = GrowExpansion(e, n, q.lo);
    n = GrowExpansion(e, n, q.hi);
  }
  // In a nonoverlapping expansion the largest nonzero component outweighs all the others together.
  EdgeValue result;
  for (int i = n - 1; i >= 0 && result.sign == 0; --i) result.sign = Sign(e[i]);
  // Smallest first, so that the rounded sum ends on the dominant component and keeps its sign.
  for (int i = 0; i < n; ++i) result.value += e[i];
  return result;
}

EdgeValue EvaluateEdge(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  const double left = (a.y - b.y) * (a.x - p.x);
  const double right = (a.x - b.x) * (a.y - p.y);
  const double plain = left - right;
  // Far from the edge (almost always) the plain value is trustworthy; near it, be exact.
  if (std::fabs(plain) > kPlainErrorBound * (std::fabs(left) + std::fabs(right))) {
    return {Sign(plain), plain};
  }
  return EvaluateEdgeExactly(a, b, p);
}

}  // namespace twinraster::truth
