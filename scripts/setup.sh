#!/usr/bin/env bash
# Installs twinraster's dependencies from Debian packages: what the program needs to build and run
# (no argument), or that plus what the tests need (--tests); with --no-vulkan, none of the Vulkan
# packages, for a build configured with -DTWINRASTER_VULKAN=OFF (docs/building.md); with
# --no-browser-module, none of the wasm32 packages the browser module needs. The names exist on Debian 12
# (bookworm) and 13 (trixie) alike; clang and libclang-rt-dev are each release's default version.
# Idempotent: packages already present are skipped, and `apt-get update` runs only when
# something is missing (so it also works on a machine where it never ran).
set -euo pipefail

packages=(
  cmake g++ make                 # build
  libvulkan-dev                  # Vulkan headers + loader (vulkan.hpp / vulkan_raii.hpp)
  mesa-vulkan-drivers            # lavapipe, the software Vulkan device
  glslang-dev glslang-tools      # glslangValidator compiles shaders/ to SPIR-V at build time
  spirv-tools                    # spirv-val checks the SPIR-V the build embeds
  libglm-dev                     # matrix and vector types
  libspng-dev zlib1g-dev         # PNG in (verify, compare): checksums and limits for untrusted files
  libdeflate-dev                 # PNG compression
  nlohmann-json3-dev             # scene files: the locating parser behind every error message
  libsimdjson-dev                # scene files: the fast parser
  libtinyobjloader-dev           # OBJ meshes a scene names (or render mesh.obj)
  libcli11-dev                   # the command line
  libstb-dev                     # bench: stb_image_write, a PNG encoder to compare against
  time                           # bench --loaders: /usr/bin/time, the peak memory of whole processes
  clang                          # the browser module's compiler, and the tests' second compiler
  lld llvm wasi-libc libc++-dev-wasm32 libclang-rt-dev-wasm32  # the browser module explain --html embeds (wasm32-wasi; llvm-ar)
)
test_packages=(
  vulkan-validationlayers        # VK_LAYER_KHRONOS_validation, used by the tests
  catch2                         # unit tests (Catch2 2 on Debian 12, 3 on Debian 13)
  libclang-rt-dev                # ASan/UBSan/libFuzzer runtimes for clang, the second compiler (sanitize preset)
  llvm                           # llvm-symbolizer: file:line in sanitizer and fuzzer reports
  python3 python3-jsonschema     # tests validate every --json output against its schema in docs/
  chromium chromium-driver python3-selenium  # tests open every kind of page in headless Chromium
  libxml2-utils                  # xmllint: render --junit's XML against docs/schemas/junit.xsd
  clang-format                   # scripts/check-format.sh: the code as .clang-format writes it
  assimp-testmodels              # glTF files no one here wrote (docs/gltf-assets.md)
)
# What a build without Vulkan does without: Vulkan, glslang and the drivers, and Chromium, whose
# Debian package depends on libvulkan1 (the browser tests are left out of such a run).
vulkan_packages=(libvulkan-dev mesa-vulkan-drivers glslang-dev glslang-tools spirv-tools vulkan-validationlayers
                 chromium chromium-driver python3-selenium)
# What a build without the browser module does without (explain --html then writes the static page
# and says why in one line).
browser_module_packages=(lld llvm wasi-libc libc++-dev-wasm32 libclang-rt-dev-wasm32)
left_out=()
for argument in "$@"; do
  case "$argument" in
    --tests) packages+=("${test_packages[@]}") ;;
    --no-vulkan) left_out+=("${vulkan_packages[@]}") ;;
    --no-browser-module) left_out+=("${browser_module_packages[@]}") ;;
    *) echo "usage: scripts/setup.sh [--tests] [--no-vulkan] [--no-browser-module]" >&2; exit 2 ;;
  esac
done
if [ ${#left_out[@]} -gt 0 ]; then
  for p in "${left_out[@]}"; do
    for i in "${!packages[@]}"; do
      if [ "${packages[i]}" = "$p" ]; then unset 'packages[i]'; fi
    done
  done
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
