#!/usr/bin/env bash
# Sets up, builds, and runs the whole test suite (CTest + Catch2). Warnings are errors.
# First the guard against tests that never run (tests/check_test_lists.cmake: a test file in no
# binary, a binary with no case, cases and CTest entries that differ), so such a run fails at once
# naming why; then everything. Fails too if the tests leave a file in the source tree outside
# build/ and out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --tests
cmake --preset release -DTWINRASTER_WERROR=ON -DTWINRASTER_BUILD_TESTS=ON >/dev/null
cmake --build --preset release

in_git=false
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then in_git=true; fi
untracked() { git status --porcelain --ignored --untracked-files=all | grep -vE '^(\?\?|!!) "?(build[^/]*|out)/' || true; }
if $in_git; then before=$(untracked); fi

if ! cmake -DBUILD_DIR="$PWD/build" -DSOURCE_DIR="$PWD" -P tests/check_test_lists.cmake; then
  echo "test.sh: the guard against tests that never run failed (its messages are above)" >&2
  exit 1
fi
ctest --preset release

if $in_git; then
  after=$(untracked)
  new=$(comm -13 <(printf '%s\n' "$before" | sort) <(printf '%s\n' "$after" | sort))
  if [ -n "$new" ]; then
    echo "test.sh: the tests left files in the source tree:" >&2
    printf '%s\n' "$new" >&2
    exit 1
  fi
fi
