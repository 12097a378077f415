#!/usr/bin/env bash
# Sets up, builds, and runs twinraster's main job on the default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release
./build/src/twinraster explain scenes/cgfs-transforms.json "$@"
