# The browser module's own build (TWINRASTER_BROWSER_MODULE_BUILD, with
# cmake/toolchains/wasm32-wasi.cmake): the packages the module's stages link, and a stand-in for
# each thing wasm32-wasi lacks, so that those stages' CMakeLists and sources stay as they are.
# cmake/BrowserModule.cmake, in the native build, runs this build; nothing else should.

# The scene loader reads JSON with nlohmann's header-only DOM: Debian ships simdjson only compiled
# for the build machine.
set(TWINRASTER_JSON_DOM nlohmann CACHE STRING "The scene loader's JSON DOM" FORCE)
# For every target, not only the scene library: the other stages include scene/'s headers too, and
# must see the same DOM (and no <simdjson.h>, which this build may not have).
add_compile_definitions(TWINRASTER_JSON_DOM_NLOHMANN)
find_package(glm REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)

# Optimised for size: the page carries the module (src/page_module/CMakeLists.txt gives the twin -O2).
set(CMAKE_CXX_FLAGS_RELEASE "-Oz -DNDEBUG")
# Exceptions are thrown (and trap: src/page_module/module_runtime.cpp), never caught.
add_compile_options($<$<COMPILE_LANGUAGE:CXX>:-fexceptions>)
# wasm32-wasi's libc++ (14) has no <filesystem> and no std::from_chars for double: this folder's
# <filesystem> keeps paths as text and refuses every file (the module reads none), and its
# <charconv> adds the double overload. A system folder, searched before libc++'s own headers.
include_directories(BEFORE SYSTEM ${PROJECT_SOURCE_DIR}/src/page_module/browser)

# No threads: cpu/ runs its parts in turn (cpu/thread_pool_serial.cpp), and links nothing for them.
add_library(Threads::Threads INTERFACE IMPORTED)

# tinyobjloader, from its header (Debian's library is compiled for the build machine only): the
# implementation the header carries, compiled here, in double as the native build links it.
add_library(twinraster_tinyobjloader STATIC ${PROJECT_SOURCE_DIR}/src/page_module/browser/tinyobjloader.cpp)
target_compile_definitions(twinraster_tinyobjloader PUBLIC TINYOBJLOADER_USE_DOUBLE)
add_library(tinyobjloader::tinyobjloader_double ALIAS twinraster_tinyobjloader)
