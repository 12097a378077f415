#!/usr/bin/env bash
# Sets up, builds, and runs the whole test suite (CTest + Catch2). Warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release -DTWINRASTER_WERROR=ON >/dev/null
cmake --build --preset release
ctest --preset release
