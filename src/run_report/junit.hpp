// `render --junit FILE`: the batch as JUnit XML, one testcase per scene, for CI systems (Jenkins,
// GitLab, GitHub's test reporters), as deqp-runner and ctest write it. Its shape is the one the
// Jenkins xUnit plugin's JUnit schema describes (docs/schemas/junit.xsd, checked by the tests).
#pragma once

#include "run/batch_result.hpp"

#include <string>

namespace twinraster::run_report {

// errors: bad input and crashed drivers; failures: differing images. Each failure's message says
// why (VerdictReason); the scene's report lines are its system-out. The counts are the batch's.
std::string JUnitXml(const run::BatchResult& batch, bool verify_asked);

}  // namespace twinraster::run_report
