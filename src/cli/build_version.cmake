# Writes build_version.hpp: the project version and, in a git checkout, `git describe --always`
# with "-dirty" when tracked files differ from HEAD (empty outside a checkout, e.g. a tarball).
# It runs at every build rather than once at configure time, so the commit never lags behind the
# tree the binary was built from; configure_file() rewrites the header only when it changes.
# Run as: cmake -DSOURCE_DIR=... -DVERSION=... -DGIT=... -DINPUT=... -DOUTPUT=... -P build_version.cmake
set(TWINRASTER_GIT_DESCRIBE "")
if(GIT AND EXISTS "${SOURCE_DIR}/.git")
  # No optional locks: other people and tools run git in this tree at the same time, and neither
  # command below should touch .git/index.lock.
  set(ENV{GIT_OPTIONAL_LOCKS} 0)
  execute_process(COMMAND "${GIT}" describe --always WORKING_DIRECTORY "${SOURCE_DIR}"
                  OUTPUT_VARIABLE describe RESULT_VARIABLE describe_failed OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT describe_failed)
    # What `git describe --dirty` adds, without its index refresh (which takes the index lock).
    execute_process(COMMAND "${GIT}" status --porcelain --untracked-files=no WORKING_DIRECTORY "${SOURCE_DIR}"
                    OUTPUT_VARIABLE changes RESULT_VARIABLE status_failed ERROR_QUIET)
    if(NOT status_failed AND NOT changes STREQUAL "")
      string(APPEND describe "-dirty")
    endif()
    set(TWINRASTER_GIT_DESCRIBE "${describe}")
  endif()
endif()
configure_file("${INPUT}" "${OUTPUT}" @ONLY)
