// The bench's results drawn: time against error for every method and scene, and the scale
// section's cost against instance count, as SVG files and as pages that hold them with their
// tables. They read BenchResult and ScaleResult; nothing here measures anything.
#pragma once

#include "bench/bench_suite.hpp"
#include "bench/scale_bench.hpp"

#include <string>

namespace twinraster::bench_report {

// Every method's vertex-stage time per million vertices against its vertex error, all scenes.
std::string BenchChartSvg(const bench::BenchResult& result);
// The page: that chart, then one small plot per scene of each method's whole-frame time against
// the pixels its image differs from the truth's, then the bench's own table.
std::string BenchPageHtml(const bench::BenchResult& result, const std::string& table);

// Time against instance count for lavapipe (instanced and F per draw), the twin and the verifier.
std::string ScaleChartSvg(const bench::ScaleResult& result);
// Every stage against instance count.
std::string ScaleStagesSvg(const bench::ScaleResult& result);
std::string ScalePageHtml(const bench::ScaleResult& result, const std::string& table);

}  // namespace twinraster::bench_report
