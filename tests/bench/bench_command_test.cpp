// `twinraster bench` as a user runs it: the table, the files it writes, and its errors.
#include "bench/bench_suite.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

using namespace twinraster;

TEST_CASE("bench --json keeps every summary key whatever ran: null where nothing was measured", "[bench][cli]") {
  const test::CliResult r = test::RunCli({"bench", "--runs", "1", "--only", "cgfs-scene", "--methods", "steps-f32",
                                          "--scenes", test::SourcePath("scenes").string(), "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto summary = nlohmann::json::parse(r.out)["summary"];
  for (const char* method : {"compose-f64", "compose-f32", "steps-f32", "camera-relative"}) {
    INFO(method);
    REQUIRE(summary["far_1e7_vertex_error_px"].contains(method));
    REQUIRE(summary["far_1e7_vertex_error_px"][method].is_null());  // hard/far-1e7 did not run
    REQUIRE(summary["vertex_ms_per_million_vertices"].contains(method));
  }
  REQUIRE(summary["vertex_ms_per_million_vertices"]["scene"] == "cgfs-scene");
  REQUIRE(summary["vertex_ms_per_million_vertices"]["steps-f32"].get<double>() > 0);
  REQUIRE(summary["vertex_ms_per_million_vertices"]["compose-f64"].is_null());
  REQUIRE(summary["z_fighting_onset_near_over_far"]["standard"].is_null());
  REQUIRE(summary["z_fighting_onset_near_over_far"]["reversed"].is_null());
  REQUIRE(summary["cpu_twin_over_lavapipe"] == nlohmann::json::array());
  REQUIRE(summary["cpu_twin_over_swiftshader"] == nlohmann::json::array());
}

TEST_CASE("bench's summary has a section only for what ran, and says none down to a ratio only when measured",
          "[bench][cli]") {
  const std::string scenes = test::SourcePath("scenes").string();
  const test::CliResult chapter = test::RunCli(
      {"bench", "--runs", "1", "--only", "cgfs-scene", "--methods", "compose-f64,cpu-twin", "--scenes", scenes});
  INFO(chapter.out << chapter.err);
  REQUIRE(chapter.exit_code == 0);
  CHECK_THAT(chapter.out, HasSubstring("medians of 1 run; "));
  CHECK_THAT(chapter.out, HasSubstring("Vertex stage, ms per million vertices (cgfs-scene, 8 vertices):\n"
                                       "  compose-f64: "));
  CHECK(chapter.out.find("Vertex error at 1e7") == std::string::npos);  // hard/far-1e7 did not run
  CHECK(chapter.out.find("Z-fighting") == std::string::npos);           // nor any depth-ratio scene
  CHECK(chapter.out.find("none down to") == std::string::npos);

  // One standard depth-ratio scene on the twin: its line is a measured result, the reversed one
  // (not run) is left out, and with no vertex method there is no vertex-stage heading.
  const test::CliResult depth = test::RunCli(
      {"bench", "--runs", "1", "--only", "depth-ratio-1e-1.json", "--methods", "cpu-twin", "--scenes", scenes});
  INFO(depth.out << depth.err);
  REQUIRE(depth.exit_code == 0);
  CHECK_THAT(depth.out,
             HasSubstring("largest near/far that fights):\n  standard Z: none down to near/far = 1.00e-01\n"));
  CHECK(depth.out.find("reversed Z:") == std::string::npos);
  CHECK(depth.out.find("Vertex stage") == std::string::npos);
  CHECK(depth.out.find("Vertex error at 1e7") == std::string::npos);
}

TEST_CASE("RunBench reports each row through on_row as it is measured, in order, numbered of the total", "[bench]") {
  bench::BenchOptions options;
  options.scenes_dir = test::SourcePath("scenes");
  options.runs = 1;
  options.only = "cgfs-";
  options.methods = {"compose-f64", "camera-relative", "cpu-twin"};
  std::vector<bench::BenchRow> seen;
  std::vector<std::size_t> numbers, totals;
  options.on_row = [&](const bench::BenchRow& row, std::size_t done, std::size_t total) {
    seen.push_back(row);
    numbers.push_back(done);
    totals.push_back(total);
  };
  const bench::BenchResult result = bench::RunBench(options);
  // Three cgfs-* scenes, each with two vertex methods and the twin with 1 thread (and with every core).
  REQUIRE(result.rows.size() >= 9);
  REQUIRE(seen.size() == result.rows.size());
  for (std::size_t i = 0; i < seen.size(); ++i) {
    INFO(i);
    REQUIRE(numbers[i] == i + 1);
    REQUIRE(totals[i] == result.rows.size());
    REQUIRE(seen[i].scene == result.rows[i].scene);
    REQUIRE(seen[i].method == result.rows[i].method);
    REQUIRE(seen[i].threads == result.rows[i].threads);
    REQUIRE(seen[i].frame_ms == result.rows[i].frame_ms);
  }
}

TEST_CASE("bench rejects bad options with exit code 2", "[bench][cli]") {
  REQUIRE(test::RunCli({"bench", "--runs", "0"}).exit_code == 2);
  REQUIRE(test::RunCli({"bench", "--scenes", "/nonexistent"}).exit_code == 2);
  REQUIRE(test::RunCli({"bench", "extra"}).exit_code == 2);
}

TEST_CASE("bench --methods runs only the named code paths, and without Vulkan when lavapipe is not one",
          "[bench][cli]") {
  const test::CliResult r =
      test::RunCli({"bench", "--runs", "1", "--only", "far-1e3", "--methods", "steps-f32,cpu-twin", "--scenes",
                    test::SourcePath("scenes").string(), "--json"},
                   {"VK_ICD_FILENAMES=/nonexistent/icd.json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto rows = nlohmann::json::parse(r.out)["rows"];
  // steps-f32, then the twin with one thread and (on a machine with more) with every core.
  REQUIRE(rows.size() >= 2);
  REQUIRE(rows.size() <= 3);
  REQUIRE(rows[0]["method"] == "steps-f32");
  for (std::size_t i = 1; i < rows.size(); ++i) REQUIRE(rows[i]["method"] == "cpu-twin");
  const test::CliResult bad = test::RunCli({"bench", "--methods", "compose-f16"});
  REQUIRE(bad.exit_code == 2);
  REQUIRE(bad.err.find("unknown method \"compose-f16\"") != std::string::npos);
}
