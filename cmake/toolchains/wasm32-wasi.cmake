# Compiles twinraster's browser module (TWINRASTER_BROWSER_MODULE_BUILD) for WebAssembly with
# Debian's own clang and its wasm32-wasi packages: wasi-libc (the C library, musl's), libc++ for
# wasm32 and its runtime, and lld (wasm-ld). Headers come from clang's wasm32-wasi include paths
# (/usr/include/wasm32-wasi), libraries from /usr/lib/wasm32-wasi; header-only CMake packages (glm,
# nlohmann's JSON) from the build machine. It names no clang version, so Debian 12's clang 14 and
# Debian 13's clang 19 both serve. The native build uses it through src/page_module/, never by hand.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR wasm32)
set(CMAKE_C_COMPILER clang)
set(CMAKE_CXX_COMPILER clang++)
set(CMAKE_C_COMPILER_TARGET wasm32-wasi)
set(CMAKE_CXX_COMPILER_TARGET wasm32-wasi)
# The compiler checks compile only: a wasm32-wasi program needs no try-run, and the module is a
# reactor (no main), linked by its own flags in src/page_module/CMakeLists.txt.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
