// Progress on standard error: status lines replaced in place and erased, lines that stay, shown
// only on a terminal, and the line each bench row prints.
#include "cli/progress.hpp"

#include "bench/bench_suite.hpp"
#include "bench_report/bench_tables.hpp"
#include "support/catch.hpp"

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

#include <sstream>

using namespace twinraster;

TEST_CASE("Progress: a status line is replaced by the next and erased at the end, a line stays", "[cli][progress]") {
  std::ostringstream out;
  {
    cli::Progress progress(&out);
    REQUIRE(progress.active());
    progress.Status("gpu: drawing...");
    progress.Status("cpu: drawing...");
    progress.Line("[1/2] a row");
    progress.Line("[2/2] a row");
    progress.Status("writing...");
  }
  REQUIRE(out.str() ==
          "\r\033[Kgpu: drawing...\r\033[Kcpu: drawing...\r\033[K[1/2] a row\n[2/2] a row\n\r\033[Kwriting...\r\033[K");
}

TEST_CASE("Progress: a status longer than a terminal line is cut, so that erasing it erases all of it",
          "[cli][progress]") {
  std::ostringstream out;
  cli::Progress progress(&out);
  progress.Status(std::string(200, 'x'));
  REQUIRE(out.str() == "\r\033[K" + std::string(69, 'x') + "...");
}

TEST_CASE("Progress without a stream writes nothing", "[cli][progress]") {
  cli::Progress progress(nullptr);
  REQUIRE(!progress.active());
  progress.Status("drawing...");
  progress.Line("a row");
  progress.Clear();  // nothing to check but that nothing crashes; OnStandardError relies on this
  SUCCEED();
}

TEST_CASE("Progress shows on a terminal only, and never when quiet", "[cli][progress]") {
  int pipe_ends[2];
  REQUIRE(::pipe(pipe_ends) == 0);
  REQUIRE(!cli::ShowProgressOn(pipe_ends[1], false));
  ::close(pipe_ends[0]);
  ::close(pipe_ends[1]);

  // A pseudo-terminal, as an interactive shell gives a program.
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  REQUIRE(master >= 0);
  REQUIRE(::grantpt(master) == 0);
  REQUIRE(::unlockpt(master) == 0);
  const int terminal = ::open(::ptsname(master), O_RDWR | O_NOCTTY);
  REQUIRE(terminal >= 0);
  CHECK(cli::ShowProgressOn(terminal, false));
  CHECK(!cli::ShowProgressOn(terminal, true));
  ::close(terminal);
  ::close(master);
}

TEST_CASE("BenchProgressLine numbers the row and gives its figures", "[cli][progress]") {
  bench::BenchRow row;
  row.scene = "hard/far-1e5";
  row.method = "compose-f32";
  row.threads = 2;
  row.frame_ms = 0.974;
  row.vertex_error_px = 2.6213;
  row.image_error_px = 2514;
  REQUIRE(bench_report::BenchProgressLine(row, 3, 56) ==
          "[ 3/56] hard/far-1e5 compose-f32, 2 threads: frame 0.97 ms, vertex error 2.62e+00 px, image error 2514 px");
  row.method = "lavapipe";
  row.threads = 1;
  row.vertex_error_px = -1;  // whole-frame rows have no vertex error
  REQUIRE(bench_report::BenchProgressLine(row, 56, 56) ==
          "[56/56] hard/far-1e5 lavapipe, 1 thread: frame 0.97 ms, image error 2514 px");
}
