// The benchmark's results as a text table, CSV and JSON (its plots are report/bench_pages.hpp).
#pragma once

#include "bench/bench_suite.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace twinraster {

std::string BenchTable(const BenchResult& result);  // every row, then the summary

// The figures the rows add up to: vertex error far from the origin per method, the near/far
// ratio where z-fighting starts, vertex-stage cost per million vertices, CPU twin / lavapipe time.
std::string BenchSummary(const BenchResult& result);
nlohmann::ordered_json BenchSummaryJson(const BenchResult& result);
std::string BenchCsv(const BenchResult& result);
// BenchJson's "format": a consumer checks it; any change to the keys or their meaning gets a new
// number (docs/json-output.md, docs/schemas/bench.schema.json).
inline constexpr const char* kBenchJsonFormat = "twinraster.bench/2";
nlohmann::ordered_json BenchJson(const BenchResult& result);

}  // namespace twinraster
