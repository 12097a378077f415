#!/usr/bin/env bash
# Writes every output the command line makes for the repository's scenes (PNGs, JSON, text, JUnit
# XML, HTML pages) into one folder, with paths, times and thread counts masked, so that two builds
# can be compared byte for byte: a redesign that changes nothing a user sees leaves `diff -r` empty.
# Usage: scripts/output-snapshot.sh TWINRASTER OUT_DIR
#   e.g. scripts/output-snapshot.sh build/bin/twinraster /tmp/before
# Needs lavapipe and SwiftShader (setup.sh installs both); takes a few minutes.
set -uo pipefail
tool="$(realpath "$1")"
out="$2"
repo="$(cd "$(dirname "$0")/.." && pwd)"
rm -rf "$out" && mkdir -p "$out"
out="$(realpath "$out")"
cd "$repo"

scenes=()
for scene in scenes/*.json scenes/hard/*.json scenes/meshes/*.obj scenes/gltf/*.gltf scenes/gltf/*.glb; do
  [ "$scene" = scenes/one-million-cubes.json ] || scenes+=("$scene")  # minutes on the twin, no new path
done
run() {  # NAME COMMAND...: stdout, stderr and exit code of one command
  local name="$1"; shift
  "$@" >"$out/$name.out" 2>"$out/$name.err"
  echo "$?" >"$out/$name.rc"
}

for device in lavapipe swiftshader; do
  run "render-$device" "$tool" render "${scenes[@]}" --device "$device" --verify --json -q \
    -o "$out/render-$device/" --report "$out/report-$device" --junit "$out/junit-$device.xml"
done
run render-wireframe "$tool" render "${scenes[@]}" --wireframe --json -q -o "$out/render-wireframe/"
run render-book "$tool" render scenes/cgfs-scene.json scenes/cgfs-instances.json --rules book -q -o "$out/render-book/"
run render-cpu-text "$tool" render scenes/cgfs-scene.json scenes/lit-gouraud.json --backend cpu \
  -o "$out/render-cpu-text/"
run render-size "$tool" render scenes/gltf/arm.gltf scenes/meshes/gem.obj --size 320x200 --json \
  -q -o "$out/render-size/"

for scene in "${scenes[@]}"; do
  name="$(echo "${scene#scenes/}" | tr / -)"
  run "explain-$name" "$tool" explain "$scene"
  run "explain-json-$name" "$tool" explain "$scene" --json
  run "explain-html-$name" "$tool" explain "$scene" --html "$out/explain-$name.html"
done

# verify and compare read images drawn above.
for png in "$out"/render-lavapipe/*-gpu.png; do
  name="$(basename "$png" -gpu.png)"
  scene="$(ls scenes/"$name".* scenes/*/"$name".* 2>/dev/null | grep -v '\.mtl$' | head -1)"
  [ -n "$scene" ] || continue
  run "verify-$name" "$tool" verify "$scene" "$png" --json --map "$out/verify-$name-map.png"
  run "verify-coverage-$name" "$tool" verify "$scene" "$png" --coverage --json --no-map
  run "compare-$name" "$tool" compare "$png" "$out/render-swiftshader/$name-gpu.png" --json
done

# Masks what differs between two runs of one build: the output folder's and the repository's
# paths and times.
find "$out" -type f \( -name '*.out' -o -name '*.err' -o -name '*.xml' -o -name '*.html' \) -print0 |
  xargs -0 sed -i -E \
    -e "s#$out#OUT#g" -e "s#$repo#REPO#g" -e 's#"timings_ms": *\{[^}]*\}#"timings_ms": T#g' \
    -e 's#"(ms|seconds|[a-z_]*_ms|[a-z_]*_seconds|time[a-z_]*|threads)": *[0-9.e+-]+#"\1": T#g' \
    -e 's#[0-9][0-9.]*(e[+-]?[0-9]+)? ?(ms|s|µs)\b#T\2#g' \
    -e 's#(load|gpu|cpu|verify) [0-9.e+-]+([,<])#\1 T\2#g' -e 's#time="[0-9.]+"#time="T"#g' -e 's#timestamp="[^"]*"#timestamp="T"#g'
echo "snapshot written to $out"
