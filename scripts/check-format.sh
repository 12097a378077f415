#!/usr/bin/env bash
# Fails when a C++ file under src/, tests/ or fuzz/ differs from what .clang-format makes of it,
# naming each place. The files are formatted by clang-format 14 (Debian 12's); another major
# version wraps a few lines differently, so this check names the version it ran.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "check-format: clang-format is not installed (scripts/setup.sh --tests)" >&2; exit 1; }
mapfile -t files < <(git ls-files 'src/*.cpp' 'src/*.hpp' 'tests/*.cpp' 'tests/*.hpp' 'fuzz/*.cpp')
echo "check-format: $(clang-format --version | head -1), ${#files[@]} files"
clang-format --dry-run --Werror "${files[@]}"
