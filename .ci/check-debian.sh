#!/usr/bin/env bash
# Proves the README's two commands on a fresh Debian release: makes a minimal root of RELEASE
# (trixie = Debian 13, bookworm = Debian 12) with debootstrap, clones this repository's HEAD into
# it, runs `bash scripts/demo.sh` and `bash scripts/test.sh` inside it as a newcomer would (on
# bookworm, then .ci/check-mesa25-bookworm.sh: the backport's lavapipe against the twin), and
# deletes the root again. With --no-vulkan instead: installs the build and test packages but the
# Vulkan ones (scripts/setup.sh --no-vulkan), checks that no libvulkan or glslang is there,
# builds with -DTWINRASTER_VULKAN=OFF and runs that build's tests (docs/building.md, "Without
# Vulkan"). Needs root (debootstrap, mount, chroot) and the network.
#
#   .ci/check-debian.sh trixie            # both README commands on Debian 13
#   .ci/check-debian.sh bookworm --no-vulkan  # a build without Vulkan, where there is none
#   KEEP_ROOT=1 .ci/check-debian.sh trixie  # keep the root afterwards (say where)
set -euo pipefail
cd "$(dirname "$0")/.."

release="${1:-}"
mode="${2:-}"
case "$release/$mode" in
  bookworm/ | trixie/ | bookworm/--no-vulkan | trixie/--no-vulkan) ;;
  *) echo "usage: .ci/check-debian.sh bookworm|trixie [--no-vulkan]" >&2; exit 2 ;;
esac
if [ "$(id -u)" -ne 0 ]; then
  echo "check-debian: needs root (debootstrap, mount, chroot)" >&2
  exit 2
fi
. .ci/debian-mirror.sh
mirror="$(debian_mirror)"
if [ -z "$mirror" ]; then
  echo "check-debian: no Debian archive in this machine's apt sources; set DEBIAN_MIRROR" >&2
  exit 2
fi
export DEBIAN_FRONTEND=noninteractive
command -v debootstrap >/dev/null || { apt-get update -qq && apt-get install -y -qq debootstrap >/dev/null; }

root=$(mktemp -d "${TMPDIR:-/var/tmp}/twinraster-$release.XXXXXX")
mounted=()
cleanup() {
  local status=$?
  # Unmount in reverse order; a bound /dev still mounted under the root would be deleted with it,
  # so the root is removed only when nothing is mounted below it, and never across file systems.
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount "${mounted[i]}" || umount -l "${mounted[i]}" || true
  done
  if findmnt -rn -o TARGET | grep -q "^$root"; then
    echo "check-debian: something is still mounted under $root; left in place" >&2
    exit 1
  fi
  if [ -n "${KEEP_ROOT:-}" ]; then
    echo "check-debian: the root is kept in $root"
  else
    rm -rf --one-file-system "$root"
  fi
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

step() { echo "=== check-debian $release: $1 ($(date -u +%H:%M:%S))"; }
step "debootstrap --variant=minbase into $root"
debootstrap --variant=minbase "$release" "$root" "$mirror" >"$root.debootstrap.log" 2>&1 ||
  { tail -20 "$root.debootstrap.log" >&2; rm -f "$root.debootstrap.log"; exit 1; }
rm -f "$root.debootstrap.log"

# /dev/pts separately: the tests open pseudo-terminals, and a plain bind of /dev leaves it empty.
for m in proc sys dev dev/pts; do
  case "$m" in
    proc) mount -t proc proc "$root/proc" ;;
    sys) mount -t sysfs sysfs "$root/sys" ;;
    dev) mount --bind /dev "$root/dev" ;;
    dev/pts) mount --bind /dev/pts "$root/dev/pts" ;;
  esac
  mounted+=("$root/$m")
done
cp -L /etc/resolv.conf "$root/etc/resolv.conf"
# Every installed Debian names localhost in /etc/hosts (the installer, cloud images and containers
# write it); a minbase root may have none, and chromedriver's clients reach it by that name.
if ! grep -qs '\blocalhost\b' "$root/etc/hosts"; then
  printf '127.0.0.1\tlocalhost\n::1\t\tlocalhost ip6-localhost ip6-loopback\n' >>"$root/etc/hosts"
fi

# A fresh clone of what is committed, as CI and a newcomer see it (the root has no git).
git clone -q "$PWD" "$root/root/twinraster"
rm -rf "$root/root/twinraster/.git"

# The --no-vulkan run: every package but Vulkan's and the browser module's, proof that none came
# in, then the build without Vulkan and its tests: the smallest build, whose explain --html writes
# the static page and says why (a CTest entry checks that line). The browser tests need Chromium,
# whose package depends on libvulkan1: the only entries not run here (the other runs of CI run them).
no_vulkan() {
  step "bash scripts/setup.sh --tests --no-vulkan --no-browser-module"
  run "bash scripts/setup.sh --tests --no-vulkan --no-browser-module"
  step "no Vulkan and no wasm32 toolchain in the root"
  run "! dpkg-query -W -f='\${Package}\n' | grep -i -e vulkan -e glslang -e spirv -e chromium -e wasm -e wasi -e '^lld'" ||
    { echo "check-debian: a Vulkan or wasm32 package was installed" >&2; exit 1; }
  run "! find / -xdev -name 'libvulkan*' | grep . && ! command -v glslangValidator" ||
    { echo "check-debian: libvulkan or glslang is in the root" >&2; exit 1; }
  step "configure and build with -DTWINRASTER_VULKAN=OFF"
  run "cmake -S . -B build-novulkan -DTWINRASTER_VULKAN=OFF -DTWINRASTER_WERROR=ON -DTWINRASTER_BUILD_TESTS=ON \
         -DCMAKE_BUILD_TYPE=Release >/dev/null && cmake --build build-novulkan --parallel 2"
  run "./build-novulkan/bin/twinraster --version | tail -1"
  step "the tests of a build without Vulkan"
  run "cmake -DBUILD_DIR=\$PWD/build-novulkan -DSOURCE_DIR=\$PWD -P tests/check_test_lists.cmake"
  run "ctest --test-dir build-novulkan --parallel 2 --output-on-failure -E '^Pages:'"
  step "a build without Vulkan passed its tests on $release"
}

run() { chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 \
  /bin/bash -c "cd /root/twinraster && $1"; }
step "$(run 'grep PRETTY_NAME /etc/os-release | cut -d= -f2')"
if [ "$mode" = --no-vulkan ]; then
  no_vulkan
  exit 0
fi
step "bash scripts/demo.sh"
run "bash scripts/demo.sh"
run "test -s out/cgfs-transforms-gpu.png && test -s out/cgfs-transforms-cpu.png" ||
  { echo "check-debian: demo.sh wrote no PNGs" >&2; exit 1; }
step "bash scripts/test.sh"
run "bash scripts/test.sh"
# Which drivers the suite proved the twin against: lavapipe's Mesa, and SwiftShader's package.
step "drivers tested: $(run "dpkg-query -W -f='\${Package} \${Version}; ' mesa-vulkan-drivers chromium-common")"
step "both README commands passed on $release"
if [ "$release" = bookworm ]; then
  # Debian 12's backport of Mesa 25.0.7 (LLVM 15): the twin's rows for it, against that driver.
  step "bash .ci/check-mesa25-bookworm.sh"
  run "bash .ci/check-mesa25-bookworm.sh"
fi
