// `twinraster explain`'s text: a typed Explanation written as the chapter prints it, every matrix
// by its name and each traced vertex through every space. It formats only: chain/explanation.hpp
// computes every number.
#pragma once

#include "chain/explanation.hpp"

#include <string>

namespace twinraster::explain_report {

// Numbers have six significant digits; a negative zero prints as 0.
std::string ExplainText(const Explanation& explanation);

}  // namespace twinraster::explain_report
