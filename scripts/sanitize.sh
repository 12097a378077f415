#!/usr/bin/env bash
# Builds twinraster with clang, AddressSanitizer and UndefinedBehaviorSanitizer (the sanitize
# preset, in build-sanitize/) and runs the whole test suite under them. Leaks are reported by
# LeakSanitizer; tests/lsan.supp silences only the Vulkan driver's own (see docs/building.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --tests
cmake --preset sanitize >/dev/null
cmake --build --preset sanitize
ctest --preset sanitize
