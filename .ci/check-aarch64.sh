#!/usr/bin/env bash
# Proves the twin on aarch64 lavapipe without an ARM machine: cross-builds twinraster with Debian's
# g++-aarch64-linux-gnu against Debian's arm64 packages (multiarch), then runs
# `render --backend both` on a sample of shipped scenes, filled and in wireframe, under
# qemu-aarch64-static with Debian 12's arm64 lavapipe. Every scene must give 0 differing pixels
# with the twin following its aarch64 rules. Needs root (dpkg, apt-get) and the network.
#
#   .ci/check-aarch64.sh            # the sample (CI)
#   .ci/check-aarch64.sh --all      # every shipped scene, and the OBJ meshes
set -euo pipefail
cd "$(dirname "$0")/.."
all=false
case "${1:-}" in
  "") ;;
  --all) all=true ;;
  *) echo "usage: .ci/check-aarch64.sh [--all]" >&2; exit 2 ;;
esac
if [ "$(id -u)" -ne 0 ]; then
  echo "check-aarch64: needs root (dpkg --add-architecture, apt-get)" >&2
  exit 2
fi
step() { echo "=== check-aarch64: $1 ($(date -u +%H:%M:%S))"; }
export DEBIAN_FRONTEND=noninteractive
work="$PWD/build-aarch64"
mkdir -p "$work"

step "arm64 packages"
# The arm64 Vulkan drivers' ICD files would sit beside the machine's own, and every x86-64 Vulkan
# program would then try (and fail) to load them: divert them to /usr/local/lib/twinraster-arm64-icd.
mkdir -p /usr/local/lib/twinraster-arm64-icd
for icd in lvp broadcom freedreno radeon; do
  dpkg-divert --quiet --local --rename --add \
    --divert "/usr/local/lib/twinraster-arm64-icd/${icd}_icd.aarch64.json" \
    "/usr/share/vulkan/icd.d/${icd}_icd.aarch64.json"
done
if ! dpkg --print-foreign-architectures | grep -qx arm64; then
  dpkg --add-architecture arm64
fi
apt-get update -qq
apt-get install -y -qq --no-install-recommends \
  g++-aarch64-linux-gnu qemu-user-static \
  libc6-dev:arm64 libstdc++-12-dev:arm64 libvulkan-dev:arm64 mesa-vulkan-drivers:arm64 \
  libdeflate-dev:arm64 libtinyobjloader-dev:arm64 libspng-dev:arm64 libstb-dev:arm64 >/dev/null
# libsimdjson-dev does not co-install with its amd64 self (a shared file differs): unpacked into a
# sysroot that the toolchain file searches.
sysroot="$work/sysroot"
if [ ! -d "$sysroot/usr/lib/aarch64-linux-gnu/cmake/simdjson" ]; then
  rm -rf "$work/debs" && mkdir -p "$work/debs" "$sysroot"
  (cd "$work/debs" && apt-get download libsimdjson-dev:arm64 "$(apt-cache depends libsimdjson-dev:arm64 |
    awk '/Depends: libsimdjson[0-9]/ {print $2}')" 2>/dev/null)
  for deb in "$work"/debs/*.deb; do dpkg-deb -x "$deb" "$sysroot"; done
fi

step "cross-build (g++-aarch64-linux-gnu)"
TWINRASTER_ARM64_SYSROOT="$sysroot" cmake -S . -B "$work/build" \
  -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/aarch64-linux-gnu.cmake -DCMAKE_BUILD_TYPE=Release \
  -DTWINRASTER_BUILD_TESTS=OFF -DTWINRASTER_WERROR=ON -DTWINRASTER_BROWSER_MODULE=OFF >/dev/null
cmake --build "$work/build" --target twinraster -j "$(nproc)"

step "render --backend both under qemu-aarch64-static"
run() {
  LD_LIBRARY_PATH="$sysroot/usr/lib/aarch64-linux-gnu" QEMU_LD_PREFIX=/ \
    VK_ICD_FILENAMES=/usr/local/lib/twinraster-arm64-icd/lvp_icd.aarch64.json \
    qemu-aarch64-static "$work/build/bin/twinraster" "$@"
}
if $all; then
  mapfile -t scenes < <(find scenes -maxdepth 2 -name '*.json' ! -path 'scenes/bench/*' ! -name 'one-million-cubes.json' | sort)
  mapfile -t meshes < <(find scenes/meshes -name '*.obj' | sort)
else
  scenes=(scenes/cgfs-transforms.json scenes/catlike-grid.json scenes/lit-mixed.json
          scenes/tinyrenderer-style.json scenes/hard/depth-ratio-1e-4.json scenes/hard/near-plane.json
          scenes/hard/degenerate.json)
  meshes=(scenes/meshes/knot.obj)
fi
out="$work/out"
rm -rf "$out" && mkdir -p "$out/wireframe"
results="$work/results.jsonl"
: >"$results"
status=0
run render "${scenes[@]}" "${meshes[@]}" --backend both --json --quiet -o "$out" >>"$results" || status=$?
run render "${scenes[@]}" --wireframe --backend both --json --quiet -o "$out/wireframe" >>"$results" || status=$?
jobs=$((2 * ${#scenes[@]} + ${#meshes[@]}))
/usr/bin/python3 .ci/check-twin-jobs.py "$results" --label check-aarch64 --jobs "$jobs" \
  --mesa 22.3.6 --llvm 15 --bits 128 --instruction-set NEON || exit 1
if [ "$status" -ne 0 ]; then
  echo "check-aarch64: render exited $status" >&2
  exit 1
fi
step "done"
