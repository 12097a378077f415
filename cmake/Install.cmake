# cmake --install: bin/twinraster, the stage libraries and their headers, and the CMake package
# (lib/cmake/twinraster) behind find_package(twinraster): twinraster::twinraster and one
# twinraster::<stage> per library (names set in src/CMakeLists.txt).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# A project that pulls twinraster in with add_subdirectory usually does not want twinraster's
# files in its own install; it can still turn this on.
option(TWINRASTER_INSTALL "Generate twinraster's install rules" ${PROJECT_IS_TOP_LEVEL})
if(NOT TWINRASTER_INSTALL)
  return()
endif()

set(twinraster_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/twinraster)

install(TARGETS twinraster RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# Two export sets, so that only users of the GPU renderer need Vulkan: the config always loads
# twinrasterTargets.cmake and loads twinrasterGpuTargets.cmake for COMPONENTS gpu. run and bench
# are in the second set because they link gpu.
install(TARGETS twinraster_base twinraster_scene twinraster_chain twinraster_image twinraster_files
                twinraster_book twinraster_cpu twinraster_twin_rules twinraster_truth twinraster_verify twinraster_library
        EXPORT twinrasterTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS twinraster_gpu twinraster_run twinraster_bench
        EXPORT twinrasterGpuTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(export_set IN ITEMS twinrasterTargets twinrasterGpuTargets)
  install(EXPORT ${export_set} NAMESPACE twinraster:: DESTINATION ${twinraster_package_dir})
endforeach()

# Headers keep their stage folder, under the root the targets' INSTALL_INTERFACE names
# (include/twinraster/scene/scene_loader.hpp is #include "scene/scene_loader.hpp"). cli/ is the
# executable's, not a library's.
foreach(stage IN ITEMS base scene chain image files book cpu twin_rules gpu truth verify run bench)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/${stage} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/twinraster
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/src/twinraster.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/twinraster)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/twinrasterConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/package/twinrasterConfig.cmake
                              INSTALL_DESTINATION ${twinraster_package_dir})
# Before 1.0 a minor release may break the API, so 0.x accepts only its own minor version.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(twinraster_compatibility SameMinorVersion)
else()
  set(twinraster_compatibility SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/twinrasterConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY ${twinraster_compatibility})
install(FILES ${PROJECT_BINARY_DIR}/package/twinrasterConfig.cmake
              ${PROJECT_BINARY_DIR}/package/twinrasterConfigVersion.cmake
        DESTINATION ${twinraster_package_dir})
