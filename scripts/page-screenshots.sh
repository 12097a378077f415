#!/usr/bin/env bash
# Refreshes the screenshots docs/pages.md shows: runs the browser tests (tests/pages), which save
# them in build/page-screenshots/, and copies them into docs/generated/images/. Run after scripts/test.sh
# has built the release preset.
set -euo pipefail
cd "$(dirname "$0")/.."
ctest --preset release -R '^Pages: '
for shot in page-batch page-chain page-chain-lit page-chain-moving; do
  cp "build/page-screenshots/$shot.png" "docs/generated/images/$shot.png"
done
echo "page-screenshots: docs/generated/images/page-*.png updated"
