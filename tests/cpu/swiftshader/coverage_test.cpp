// SwiftShader's coverage (cpu/swiftshader/coverage.hpp): an outline scan-converted row by row at
// 4 subpixel bits, left ends inclusive and right ends exclusive (the top-left rule).
#include "cpu/swiftshader/coverage.hpp"

#include "corner_triangle.hpp"
#include "cpu/swiftshader/setup.hpp"
#include "support/catch.hpp"

#include <array>

using namespace twinraster::cpu;
using test::kCorner;
using test::Vertex;

TEST_CASE("SwiftShader coverage: a triangle's rows, top and left edges in, right and bottom edges out",
          "[cpu][swiftshader][coverage]") {
  for (int py = 0; py < 4; ++py) {
    const Span span = OutlineSpan(kCorner.data(), 3, false, 100, py);
    CHECK(span.begin == 0);     // on the left edge x = 0: covered
    CHECK(span.end == 4 - py);  // px + py = 4 is on the hypotenuse: not covered
  }
  // Row 4 holds only the bottom vertex: its centre is on the edge, not covered.
  const Span below = OutlineSpan(kCorner.data(), 3, false, 100, 4);
  CHECK(below.begin >= below.end);
}

TEST_CASE("SwiftShader coverage: the winding decides which edges end a row", "[cpu][swiftshader][coverage]") {
  // Walked the other way, every edge writes the other end: left >= right, nothing covered.
  for (int py = 0; py < 4; ++py) {
    const Span span = OutlineSpan(kCorner.data(), 3, true, 100, py);
    CHECK(span.begin >= span.end);
  }
  // Set-up's winding for these points says to walk them reversed (setup_test.cpp).
  CHECK_FALSE(OutlineWinding(Vertex(0, 0), Vertex(64, 0), Vertex(0, 64)));
}

TEST_CASE("SwiftShader coverage: spans clamp to the framebuffer's width", "[cpu][swiftshader][coverage]") {
  // A square from centre -2 to centre 6 on a framebuffer 4 pixels wide.
  const std::array<SnappedPoint, 4> square = {{{-32, 0}, {-32, 64}, {96, 64}, {96, 0}}};
  const Span span = OutlineSpan(square.data(), 4, true, 4, 1);
  CHECK(span.begin == 0);
  CHECK(span.end == 4);
}

TEST_CASE("SwiftShader coverage: rows equal a per-pixel test of the top-left rule on many triangles",
          "[cpu][swiftshader][coverage]") {
  // For a triangle (a, b, c) in 1/16 pixel with positive winding, pixel centre p is covered when each
  // edge's function is > 0, or == 0 on a top or left edge. Checked against OutlineSpan, both ends.
  const auto edge = [](const SnappedPoint& a, const SnappedPoint& b, std::int64_t x, std::int64_t y) {
    return (std::int64_t{b.y} - a.y) * (x - a.x) - (std::int64_t{b.x} - a.x) * (y - a.y);
  };
  std::uint32_t seed = 12345;
  const auto next = [&seed](int range) {
    seed = seed * 1664525u + 1013904223u;
    return static_cast<std::int32_t>((seed >> 8) % static_cast<std::uint32_t>(range));
  };
  int compared = 0;
  for (int n = 0; n < 200; ++n) {
    std::array<SnappedPoint, 3> p = {{{next(160), next(160)}, {next(160), next(160)}, {next(160), next(160)}}};
    std::array<SnappedVertex, 3> v = {Vertex(p[0].x, p[0].y), Vertex(p[1].x, p[1].y), Vertex(p[2].x, p[2].y)};
    const bool d = OutlineWinding(v[0], v[1], v[2]);
    if (!d) std::swap(p[1], p[2]);  // now wound so that every edge function is >= 0 inside
    if (edge(p[0], p[1], p[2].x, p[2].y) == 0) continue;
    for (int py = 0; py < 10; ++py) {
      const Span span = OutlineSpan(p.data(), 3, true, 10, py);
      for (int px = 0; px < 10; ++px) {
        bool inside = true;
        for (int i = 0; i < 3; ++i) {
          const SnappedPoint& a = p[static_cast<std::size_t>(i)];
          const SnappedPoint& b = p[static_cast<std::size_t>((i + 1) % 3)];
          const std::int64_t e = edge(a, b, 16 * px, 16 * py);
          // Wound this way, an edge running down (b below a) is a left edge, and a horizontal one
          // running left (b left of a) is a top edge.
          const bool top_left = b.y > a.y || (b.y == a.y && b.x < a.x);
          inside = inside && (e > 0 || (e == 0 && top_left));
        }
        const bool covered = span.begin <= px && px < span.end;
        INFO("triangle " << n << " pixel " << px << ", " << py);
        CHECK(covered == inside);
        ++compared;
      }
    }
  }
  CHECK(compared > 10000);
}
