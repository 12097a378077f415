// `twinraster bench` as a user runs it: the table, the files it writes, and its errors.
#include "support/test_support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>

using namespace twinraster;

TEST_CASE("bench --out writes the CSV, the chart and the JSON for the chosen scenes", "[bench][cli]") {
  const test::TempDir dir;
  const test::CliResult r = test::RunCli({"bench", "--runs", "1", "--only", "far-1e7", "--scenes",
                                          test::SourcePath("scenes").string(), "--out", dir.path().string(), "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  // Four methods, then the CPU twin and lavapipe with one thread and with every core.
  REQUIRE(j["rows"].size() >= 6);
  REQUIRE(j["rows"][0]["scene"] == "hard/far-1e7");
  REQUIRE(j["summary"]["far_1e7_vertex_error_px"]["camera-relative"].get<double>() < 1.0 / 256);
  for (const auto& row : j["rows"]) {
    REQUIRE(row["frame_ms"].get<double>() > 0);
    if (row["method"] == "cpu-twin" || row["method"] == "lavapipe") REQUIRE(row["image_error_px"] == 2);
  }
  const std::string csv = test::ReadFile(dir / "bench.csv");
  REQUIRE(csv.rfind("scene,method,threads,", 0) == 0);
  REQUIRE(std::count(csv.begin(), csv.end(), '\n') == 1 + static_cast<long>(j["rows"].size()));
  const std::string svg = test::ReadFile(dir / "bench.svg");
  REQUIRE(svg.rfind("<svg", 0) == 0);
  REQUIRE(svg.find("<circle") != std::string::npos);
  REQUIRE(nlohmann::json::parse(test::ReadFile(dir / "bench.json"))["rows"].size() == j["rows"].size());
}

TEST_CASE("bench rejects bad options with exit code 2", "[bench][cli]") {
  REQUIRE(test::RunCli({"bench", "--runs", "0"}).exit_code == 2);
  REQUIRE(test::RunCli({"bench", "--scenes", "/nonexistent"}).exit_code == 2);
  REQUIRE(test::RunCli({"bench", "extra"}).exit_code == 2);
}

TEST_CASE("bench --methods runs only the named code paths, and without Vulkan when lavapipe is not one", "[bench][cli]") {
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
