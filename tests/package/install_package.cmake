# Installs a twinraster build into a fresh prefix, checks what landed there, and renders the
# reference image with the installed executable (the package tests compare their consumers to it).
# Run as: cmake -DBUILD_DIR=... -DPREFIX=... -DCONFIG=... -DLIBDIR=... -DSOURCE_DIR=...
#               -DSCENE=... -DREFERENCE=... -P install_package.cmake
foreach(var IN ITEMS BUILD_DIR PREFIX LIBDIR SOURCE_DIR SCENE REFERENCE)
  if(NOT ${var})
    message(FATAL_ERROR "install_package: set -D${var}")
  endif()
endforeach()

# Fresh, so that a file an install rule no longer installs cannot linger and pass the checks.
file(REMOVE_RECURSE "${PREFIX}")
set(config_args)
if(CONFIG)
  set(config_args --config "${CONFIG}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}" ${config_args}
                OUTPUT_QUIET RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "install_package: cmake --install ${BUILD_DIR} failed (${result})")
endif()

set(expected
  bin/twinraster
  include/twinraster/twinraster.hpp
  include/twinraster/scene/scene_loader.hpp
  include/twinraster/chain/draw_list.hpp
  include/twinraster/image/image.hpp
  include/twinraster/files/png_file.hpp
  include/twinraster/book/book_renderer.hpp
  include/twinraster/cpu/cpu_renderer.hpp
  include/twinraster/gpu/gpu_renderer.hpp
  include/twinraster/base/stopwatch.hpp
  ${LIBDIR}/cmake/twinraster/twinrasterConfig.cmake
  ${LIBDIR}/cmake/twinraster/twinrasterConfigVersion.cmake
  ${LIBDIR}/cmake/twinraster/twinrasterTargets.cmake
  ${LIBDIR}/cmake/twinraster/twinrasterGpuTargets.cmake
)
foreach(stage IN ITEMS scene chain image files book cpu gpu truth run bench)
  list(APPEND expected ${LIBDIR}/libtwinraster_${stage}.a)
endforeach()
set(problems 0)
foreach(file IN LISTS expected)
  if(NOT EXISTS "${PREFIX}/${file}")
    message(SEND_ERROR "not installed: ${file}")
    math(EXPR problems "${problems} + 1")
  endif()
endforeach()
if(EXISTS "${PREFIX}/include/twinraster/cli")
  message(SEND_ERROR "installed the executable's own headers (include/twinraster/cli)")
  math(EXPR problems "${problems} + 1")
endif()

# The package must describe itself relative to its prefix, not point back into this checkout or
# this build, or at this machine's copy of a dependency.
file(GLOB package_files "${PREFIX}/${LIBDIR}/cmake/twinraster/*.cmake")
foreach(file IN LISTS package_files)
  file(READ "${file}" text)
  foreach(forbidden IN ITEMS "${SOURCE_DIR}" "${BUILD_DIR}" "libdeflate.so" "libdeflate.a")
    string(FIND "${text}" "${forbidden}" at)
    if(NOT at EQUAL -1)
      message(SEND_ERROR "${file} names ${forbidden}")
      math(EXPR problems "${problems} + 1")
    endif()
  endforeach()
endforeach()
if(problems GREATER 0)
  message(FATAL_ERROR "install_package: ${problems} problems in ${PREFIX}")
endif()

file(REMOVE "${REFERENCE}")
execute_process(COMMAND "${PREFIX}/bin/twinraster" render "${SCENE}" --backend cpu -o "${REFERENCE}"
                OUTPUT_QUIET RESULT_VARIABLE result)
if(NOT result EQUAL 0 OR NOT EXISTS "${REFERENCE}")
  message(FATAL_ERROR "install_package: the installed twinraster failed to render ${SCENE} (${result})")
endif()
message(STATUS "install_package: ${PREFIX} complete; installed twinraster rendered ${REFERENCE}")
