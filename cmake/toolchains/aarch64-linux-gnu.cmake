# Cross-compiles twinraster for 64-bit ARM Linux on an x86-64 Debian machine, against Debian's
# arm64 packages installed side by side (dpkg --add-architecture arm64) and, for a package that
# does not co-install, an extracted copy in TWINRASTER_ARM64_SYSROOT. .ci/check-aarch64.sh
# sets this up and runs the result under qemu-aarch64-static.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)

# Host programs (glslangValidator, spirv-val) from the build machine; libraries, headers and
# CMake packages from arm64's directories.
set(CMAKE_FIND_ROOT_PATH / $ENV{TWINRASTER_ARM64_SYSROOT})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
