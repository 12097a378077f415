// The benches' results as text tables, CSV and JSON, and the suite's progress line (their
// plots are bench_pages.hpp). They format the results; nothing here measures anything.
#pragma once

#include "bench/bench_suite.hpp"
#include "bench/loader_bench.hpp"
#include "bench/scale_bench.hpp"
#include "bench/verify_bench.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <string>

namespace twinraster::bench_report {

std::string BenchTable(const bench::BenchResult& result);  // every row, then the summary

// The figures the rows add up to: vertex error far from the origin per method, the near/far
// ratio where z-fighting starts, vertex-stage cost per million vertices, CPU twin / lavapipe time.
std::string BenchSummary(const bench::BenchResult& result);
nlohmann::ordered_json BenchSummaryJson(const bench::BenchResult& result);
std::string BenchCsv(const bench::BenchResult& result);
// BenchJson's "format": a consumer checks it; any change to the keys or their meaning gets a new
// number (docs/json-output.md, docs/schemas/bench.schema.json).
inline constexpr const char* kBenchJsonFormat = "twinraster.bench/2";
nlohmann::ordered_json BenchJson(const bench::BenchResult& result);

// "[ 3/56] hard/far-1e5 compose-f32, 2 threads: frame 0.97 ms, vertex error 2.62e+00 px, image error 2514 px"
std::string BenchProgressLine(const bench::BenchRow& row, std::size_t done, std::size_t total);

// bench --scale (scale_tables.cpp).
inline constexpr const char* kScaleJsonFormat = "twinraster.bench-scale/4";
std::string ScaleTable(const bench::ScaleResult& result);
std::string ScaleCsv(const bench::ScaleResult& result);
nlohmann::ordered_json ScaleJson(const bench::ScaleResult& result);

// bench --verify (verify_bench_tables.cpp).
std::string VerifyBenchTable(const bench::VerifyBenchResult& result);
nlohmann::ordered_json VerifyBenchJson(const bench::VerifyBenchResult& result);

// bench --loaders (loader_bench_tables.cpp).
inline constexpr const char* kLoaderBenchJsonFormat = "twinraster.bench-loaders/1";
std::string LoaderBenchTable(const bench::LoaderBenchResult& result);
nlohmann::ordered_json LoaderBenchJson(const bench::LoaderBenchResult& result);

}  // namespace twinraster::bench_report
