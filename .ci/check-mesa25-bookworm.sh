#!/usr/bin/env bash
# Proves the twin's rows for Mesa 25.0.7 built with LLVM 15 (Debian 12's bookworm-backports) against
# that very driver, on its three CPU paths: AVX2+FMA at 256 and at 128 bits (LP_NATIVE_VECTOR_WIDTH),
# and sse4.1 (GALLIUM_OVERRIDE_CPU_CAPS). It downloads the backport's lavapipe and the newer libdrm
# it needs into a work folder with apt's own lists kept there (nothing is installed), and runs
# `render --backend both` on every shipped scene, filled and in wireframe, and the OBJ meshes:
# every job must be bit-exact (.ci/check-twin-jobs.py). At 128 bits lavapipe may crash on a
# few scenes (docs/mesa-128bit-crash.md). Run on Debian 12 (CI runs it inside check-debian.sh's
# bookworm root) after building build/bin/twinraster; needs the network, not root.
set -euo pipefail
cd "$(dirname "$0")/.."
. .ci/debian-mirror.sh
step() { echo "=== check-mesa25-bookworm: $1 ($(date -u +%H:%M:%S))"; }
exe="$PWD/build/bin/twinraster"
[ -x "$exe" ] || { echo "check-mesa25-bookworm: build $exe first" >&2; exit 2; }
. /etc/os-release
[ "${VERSION_CODENAME:-}" = bookworm ] ||
  { echo "check-mesa25-bookworm: needs Debian 12 (bookworm), whose LLVM 15 the backport links; this is ${PRETTY_NAME:-unknown}" >&2; exit 2; }
mirror="$(debian_mirror)"
[ -n "$mirror" ] || { echo "check-mesa25-bookworm: no Debian archive in this machine's apt sources; set DEBIAN_MIRROR" >&2; exit 2; }
work="$PWD/build-mesa25"
rm -rf "$work" && mkdir -p "$work/apt/lists/partial" "$work/apt/cache" "$work/debs" "$work/root"

step "lavapipe from bookworm-backports"
echo "deb [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $mirror bookworm-backports main" >"$work/apt/sources.list"
apt_options=(-o "Dir::Etc::SourceList=$work/apt/sources.list" -o Dir::Etc::SourceParts=/dev/null
             -o "Dir::State::Lists=$work/apt/lists" -o "Dir::Cache=$work/apt/cache" -o APT::Sandbox::User=root)
apt-get "${apt_options[@]}" update -qq
(cd "$work/debs" && apt-get "${apt_options[@]}" download -qq \
  mesa-vulkan-drivers/bookworm-backports libdrm2/bookworm-backports libdrm-amdgpu1/bookworm-backports)
for deb in "$work"/debs/*.deb; do dpkg-deb -x "$deb" "$work/root"; done
lib="$work/root/usr/lib/x86_64-linux-gnu"
printf '{"file_format_version": "1.0.0", "ICD": {"library_path": "%s/libvulkan_lvp.so", "api_version": "1.4.0"}}\n' \
  "$lib" >"$work/lvp_icd.json"

mapfile -t scenes < <(find scenes -name '*.json' ! -path 'scenes/bench/*' ! -name 'one-million-cubes.json' | sort)
mapfile -t meshes < <(find scenes/meshes -name '*.obj' | sort)
jobs=$((2 * ${#scenes[@]} + ${#meshes[@]}))
status=0
# path label, bits, instruction set, crashes allowed (of 91: a quarter, as the 128-bit test allows),
# the variable that takes the path
while read -r label bits isa crashes variable; do
  [ "$variable" = - ] && variable=
  step "$label"
  results="$work/$label.jsonl"
  out="$work/out-$label"
  mkdir -p "$out/wireframe"
  # render exits 5 when the driver crashed on a scene (the checker counts those); any other
  # failure stops here.
  for wireframe in "" --wireframe; do
    jobs_here=("${scenes[@]}")
    if [ -z "$wireframe" ]; then jobs_here+=("${meshes[@]}"); else jobs_here+=(--wireframe); fi
    code=0
    env $variable LD_LIBRARY_PATH="$lib" VK_ICD_FILENAMES="$work/lvp_icd.json" "$exe" render "${jobs_here[@]}" \
      --backend both --json --quiet -o "$out${wireframe:+/wireframe}" >>"$results" </dev/null || code=$?
    if [ "$code" -ne 0 ] && [ "$code" -ne 5 ]; then
      echo "check-mesa25-bookworm: render exited $code on $label" >&2
      status=1
    fi
  done
  /usr/bin/python3 .ci/check-twin-jobs.py "$results" </dev/null --label "Mesa 25.0.7 (LLVM 15), $label" --jobs "$jobs" \
    --mesa 25.0.7 --llvm 15 --bits "$bits" --instruction-set "$isa" --max-crashes "$crashes" || status=1
done <<'PATHS'
avx2-256 256 AVX2+FMA 0 -
avx2-128 128 AVX2+FMA 22 LP_NATIVE_VECTOR_WIDTH=128
sse4.1 128 SSE4.1 0 GALLIUM_OVERRIDE_CPU_CAPS=sse4.1
PATHS
[ "$status" -eq 0 ] && step "every row proven" || echo "check-mesa25-bookworm: a row failed (above)" >&2
exit "$status"
