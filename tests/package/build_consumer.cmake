# Configures and builds tests/package/consumer with the main build's compiler and flags, runs it
# on a scene, and checks its PNG equals the reference twinraster rendered. Either against an
# installed prefix (-DPREFIX, find_package) or from source (-DTWINRASTER_SOURCE_DIR,
# add_subdirectory). Any failing step fails the test.
# Run as: cmake -DCONSUMER_SOURCE=... -DCONSUMER_BUILD=... -DGENERATOR=... -DMAKE_PROGRAM=...
#   -DCXX_COMPILER=... -DBUILD_TYPE=... -DCXX_FLAGS=... -DEXE_LINKER_FLAGS=...
#   (-DPREFIX=... | -DTWINRASTER_SOURCE_DIR=... [-DWERROR=ON|OFF] [-DVULKAN=ON|OFF]) -DSCENE=... -DREFERENCE=... -DTWINRASTER_EXE=...
#   -P build_consumer.cmake
foreach(var IN ITEMS CONSUMER_SOURCE CONSUMER_BUILD GENERATOR CXX_COMPILER SCENE REFERENCE TWINRASTER_EXE)
  if(NOT ${var})
    message(FATAL_ERROR "build_consumer: set -D${var}")
  endif()
endforeach()

set(configure_args
  -G "${GENERATOR}"
  "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
  "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
  "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
  "-DCMAKE_EXE_LINKER_FLAGS=${EXE_LINKER_FLAGS}")
if(MAKE_PROGRAM)
  list(APPEND configure_args "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
endif()
if(PREFIX)
  # The package changes with every install, and the consumer is one file: start from nothing.
  file(REMOVE_RECURSE "${CONSUMER_BUILD}")
  list(APPEND configure_args "-DCMAKE_PREFIX_PATH=${PREFIX}")
elseif(TWINRASTER_SOURCE_DIR)
  # Kept between runs: the build is incremental, like anyone's add_subdirectory build.
  list(APPEND configure_args "-DTWINRASTER_SOURCE_DIR=${TWINRASTER_SOURCE_DIR}")
  if(DEFINED WERROR)
    list(APPEND configure_args "-DTWINRASTER_WERROR=${WERROR}")  # twinraster's sources, as in the main build
  endif()
  if(DEFINED VULKAN)
    list(APPEND configure_args "-DTWINRASTER_VULKAN=${VULKAN}")  # a build without Vulkan builds its consumer so
  endif()
else()
  message(FATAL_ERROR "build_consumer: set -DPREFIX or -DTWINRASTER_SOURCE_DIR")
endif()

# Runs one step; its output goes to the test's log, and a non-zero exit fails the test by name.
function(run_step step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "build_consumer: ${step} failed (${result})")
  endif()
endfunction()

run_step(configure "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE}" -B "${CONSUMER_BUILD}" ${configure_args})
if(PREFIX)
  # find_package must have found this prefix, not some other twinraster on the machine.
  file(STRINGS "${CONSUMER_BUILD}/CMakeCache.txt" found REGEX "^twinraster_DIR:")
  string(FIND "${found}" "${PREFIX}/" at)
  if(NOT at GREATER -1)
    message(FATAL_ERROR "build_consumer: find_package used ${found}, not ${PREFIX}")
  endif()
endif()

set(config_args)
if(BUILD_TYPE)
  set(config_args --config "${BUILD_TYPE}")
endif()
# Two jobs at most: the machine has two cores, shared.
run_step(build "${CMAKE_COMMAND}" --build "${CONSUMER_BUILD}" --parallel 2 ${config_args})

set(program "${CONSUMER_BUILD}/render_cpu")
if(BUILD_TYPE AND EXISTS "${CONSUMER_BUILD}/${BUILD_TYPE}/render_cpu")
  set(program "${CONSUMER_BUILD}/${BUILD_TYPE}/render_cpu")  # a multi-config generator
endif()
set(output "${CONSUMER_BUILD}/consumer.png")
file(REMOVE "${output}")
run_step("rendering ${SCENE}" "${program}" "${SCENE}" "${output}")
# Exit 0 only for two readable PNGs of one size with no differing pixel.
run_step("comparing with ${REFERENCE}" "${TWINRASTER_EXE}" compare "${output}" "${REFERENCE}")
