#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan, UBSan; the fuzz preset, in build-fuzz/) and runs each
# for a bounded time (default 60 s each; FUZZ_SECONDS=N to change):
#   scene_loader_fuzzer on a copy of the shipped scenes, with fuzz/scene.dict;
#   gltf_fuzzer (bytes -> glTF reader -> scene) on assimp-testmodels' glTF files;
#   png_reader_fuzzer (bytes -> PNG reader -> verify -> map) on the project's own render of a
#   scene at 64 x 64 written in every PNG encoding (scripts/make-test-pngs.py --encodings-of),
#   plus tests/files/pngs/ (every valid encoding, and one malformed file per known class).
# First replays every input saved in fuzz/regressions/<fuzzer>/. A finding (a crash, an unexpected
# exception, a leak, UB, a hang over 30 s, memory past the limit) fails the script; its input is
# left in build-fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --tests
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
seconds="${FUZZ_SECONDS:-60}"
mkdir -p build-fuzz/findings
shopt -s nullglob

# Runs fuzzer $1 on corpus folder $2 with the remaining arguments, after its saved inputs.
run() {
  local name=$1 corpus=$2
  shift 2
  local regressions=(fuzz/regressions/"$name"/*)
  if [ ${#regressions[@]} -gt 0 ]; then
    echo "fuzz: $name: replaying ${#regressions[@]} saved input(s) from fuzz/regressions/$name/"
    "./build-fuzz/fuzz/$name" "$@" "${regressions[@]}"
  fi
  echo "fuzz: $name: $(ls "$corpus" | wc -l) seeds, ${seconds} s"
  "./build-fuzz/fuzz/$name" "$corpus" -max_total_time="$seconds" "$@" \
    -artifact_prefix="build-fuzz/findings/$name-" -print_final_stats=1
}

# The scene loader. The largest scene it accepts by design (2^24 instances, kMaxInstances) holds
# 2 GiB of instances and takes ~7 s to load under ASan: the limits leave room for it, so that only
# what exceeds the loader's own bounds is a finding. The seeds: every shipped scene small enough
# for -max_len (a copy: libFuzzer adds to its corpus directory, and scenes/ is never written),
# named after their path, so no two collide.
scenes=build-fuzz/run/scenes
rm -rf "$scenes" && mkdir -p "$scenes"
while IFS= read -r scene; do
  cp "$scene" "$scenes/$(echo "$scene" | tr / _)"
done < <(find scenes -name '*.json' -size -64k | sort)
run scene_loader_fuzzer "$scenes" -dict=fuzz/scene.dict -timeout=30 -rss_limit_mb=4096 -max_len=65536

# The glTF reader, on the .gltf and .glb files of Debian's assimp-testmodels that fit -max_len
# (those whose buffers are separate files reach only the JSON: the fuzzer reads no other file).
# The bounds are GltfLimits' defaults: a finding is what escapes them.
gltfs=build-fuzz/run/gltf
rm -rf "$gltfs" && mkdir -p "$gltfs"
while IFS= read -r file; do
  cp "$file" "$gltfs/$(echo "${file#/usr/share/assimp/models/}" | tr / _)"
done < <(find /usr/share/assimp/models/glTF2 \( -name '*.gltf' -o -name '*.glb' \) -size -256k | sort)
run gltf_fuzzer "$gltfs" -timeout=30 -rss_limit_mb=4096 -max_len=262144

# The image path. A PNG may declare up to 16384 x 16384 (1 GiB of RGBA) only where no canvas is
# given; here the canvas is 64 x 64 and checked before decoding, so one allocation over 64 MB is
# a finding (-malloc_limit_mb), as is a process over 2 GB. The fuzz preset builds the reader
# without checksum checks, so that mutations reach the decoder and the verifier. The seeds: the twin's render of the chapter's scene at 64 x 64 (the release
# build's twinraster, built here if missing), in every encoding, and the reader's test files.
pngs=build-fuzz/run/pngs
rm -rf "$pngs" && mkdir -p "$pngs"
cmake --preset release >/dev/null
cmake --build --preset release --target twinraster >/dev/null
/usr/bin/python3 -c 'import json, sys
scene = json.load(open("scenes/cgfs-transforms.json"))
scene["canvas"]["width"] = scene["canvas"]["height"] = 64
json.dump(scene, open(sys.argv[1], "w"))' build-fuzz/run/small-scene.json
./build/bin/twinraster render build-fuzz/run/small-scene.json --backend cpu -q -o build-fuzz/run/small.png
/usr/bin/python3 scripts/make-test-pngs.py --encodings-of build-fuzz/run/small.png --out "$pngs"
for f in tests/files/pngs/valid/*.png tests/files/pngs/malformed/*.png; do
  cp "$f" "$pngs/$(basename "$(dirname "$f")")-$(basename "$f")"
done
run png_reader_fuzzer "$pngs" -timeout=30 -rss_limit_mb=2048 -malloc_limit_mb=64 -max_len=262144
