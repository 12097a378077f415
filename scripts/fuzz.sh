#!/usr/bin/env bash
# Builds the scene loader's libFuzzer target (clang, ASan, UBSan) and runs it for a bounded time
# (default 60 s; FUZZ_SECONDS=N to change) on a copy of the shipped scenes as corpus. A finding
# fails the script; its input is left in build-fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
seconds="${FUZZ_SECONDS:-60}"
work=build-fuzz/run
rm -rf "$work" && mkdir -p "$work/corpus" build-fuzz/findings
find scenes -name '*.json' -size -64k -exec cp {} "$work/corpus/" \;
echo "fuzz: $(ls "$work/corpus" | wc -l) seed scenes, ${seconds} s"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ./build-fuzz/fuzz/scene_loader_fuzzer "$work/corpus" -dict=fuzz/scene.dict -max_total_time="$seconds" \
  -timeout=10 -rss_limit_mb=2048 -max_len=65536 -artifact_prefix=build-fuzz/findings/ -print_final_stats=1
