#include "cli/commands.hpp"

namespace twinraster {

int WorseExit(int a, int b) {
  // Inconclusive (6) is milder than every problem (1 to 5) and worse only than success (0).
  const auto rank = [](int code) { return code == kExitInconclusive ? 1 : code == kExitOk ? 0 : code + 1; };
  return rank(a) >= rank(b) ? a : b;
}

}  // namespace twinraster
