#!/usr/bin/env bash
# Sets up, builds, and renders the default scene on lavapipe and on the CPU twin, comparing them.
# Writes out/cgfs-transforms-gpu.png and out/cgfs-transforms-cpu.png. Extra arguments go to render.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# The demo needs no test package: the tests are left out of this configure.
cmake --preset release -DTWINRASTER_BUILD_TESTS=OFF >/dev/null
cmake --build --preset release --target twinraster
mkdir -p out
./build/bin/twinraster render scenes/cgfs-transforms.json -o out/cgfs-transforms.png "$@"
