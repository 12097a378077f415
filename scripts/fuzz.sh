#!/usr/bin/env bash
# Builds the scene loader's libFuzzer target (clang, ASan, UBSan; the fuzz preset, in build-fuzz/)
# and runs it for a bounded time (default 60 s; FUZZ_SECONDS=N to change) on a copy of the shipped
# scenes as corpus, with fuzz/scene.dict. First replays every input saved in fuzz/regressions/.
# A finding (a crash, an exception other than SceneError, a leak, UB, a hang over 30 s, over
# 4 GiB) fails the script; its input is left in build-fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --tests
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
fuzzer=./build-fuzz/fuzz/scene_loader_fuzzer
export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The largest scene the loader accepts by design (2^24 instances, kMaxInstances) holds 2 GiB of
# instances and takes ~7 s to load under ASan: the limits leave room for it, so that only what
# exceeds the loader's own bounds is a finding.
limits=(-timeout=30 -rss_limit_mb=4096 -max_len=65536)

shopt -s nullglob
regressions=(fuzz/regressions/*)
if [ ${#regressions[@]} -gt 0 ]; then
  echo "fuzz: replaying ${#regressions[@]} saved input(s) from fuzz/regressions/"
  "$fuzzer" "${limits[@]}" "${regressions[@]}"
fi

seconds="${FUZZ_SECONDS:-60}"
work=build-fuzz/run
rm -rf "$work" && mkdir -p "$work/corpus" build-fuzz/findings
# The seeds: every shipped scene small enough for -max_len (a copy: libFuzzer adds to its corpus
# directory, and scenes/ is never written). Named after their path, so no two collide.
while IFS= read -r scene; do
  cp "$scene" "$work/corpus/$(echo "$scene" | tr / _)"
done < <(find scenes -name '*.json' -size -64k | sort)
echo "fuzz: $(ls "$work/corpus" | wc -l) seed scenes, ${seconds} s"
"$fuzzer" "$work/corpus" -dict=fuzz/scene.dict -max_total_time="$seconds" "${limits[@]}" \
  -artifact_prefix=build-fuzz/findings/ -print_final_stats=1
