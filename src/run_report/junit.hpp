// `render --junit FILE`: the batch as JUnit XML, one testcase per scene, for CI systems (Jenkins,
// GitLab, GitHub's test reporters), as deqp-runner and ctest write it. Its shape is the one the
// Jenkins xUnit plugin's JUnit schema describes (docs/schemas/junit.xsd, checked by the tests).
#pragma once

#include "run/run_record.hpp"

#include <string>
#include <vector>

namespace twinraster::report {

// errors: bad input and crashed drivers; failures: differing images. Each failure's message says
// why (VerdictReason); the scene's report lines are its system-out.
std::string JUnitXml(const std::vector<run::RunRecord>& records, double total_ms, bool verify_asked);

}  // namespace twinraster::report
