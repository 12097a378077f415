# Writes which stages each folder of src/ may include, derived from the links of the libraries the
# folder defines: its own stage and, transitively, those of every twinraster target they link.
# check_layers.cmake reads the file; the data path's order is written once, in the links. It reads
# no source file; it also lists the .cpp files each folder compiles in this configuration.
#
# A target's stage is the folder its CMakeLists.txt is in (the target's SOURCE_DIR): src/<stage>/
# and any folder under it is <stage>, a folder at the top of the repository (shaders/) its name. So a new folder of src/
# needs no entry anywhere: its CMakeLists.txt defines its library (twinraster_<folder>, by the
# house's naming) and links the stages it uses. A folder links what it links directly (PRIVATE
# too); through those, only what they pass on (PUBLIC and INTERFACE links).
#
# Call at the end of configuring (every target and link defined):
#   twinraster_write_allowed_layers(<repository> <file to write>)

# `target`'s stage, or "" when it is no stage's (an imported target, or one defined elsewhere).
function(twinraster_stage_of target source_dir out)
  set(${out} "" PARENT_SCOPE)
  if(NOT TARGET ${target} OR NOT target MATCHES "^twinraster")
    return()
  endif()
  get_target_property(aliased ${target} ALIASED_TARGET)
  if(aliased)
    set(target ${aliased})
  endif()
  get_target_property(imported ${target} IMPORTED)
  if(imported)
    return()
  endif()
  get_target_property(dir ${target} SOURCE_DIR)
  file(RELATIVE_PATH where ${source_dir} ${dir})
  if(where MATCHES "^src/([^/]+)")
    set(${out} ${CMAKE_MATCH_1} PARENT_SCOPE)
  elseif(where MATCHES "^[^/.]+$")
    set(${out} ${where} PARENT_SCOPE)
  endif()
endfunction()

# The targets a link list names: $<BUILD_INTERFACE:x> is x; $<LINK_ONLY:x> (a PRIVATE link seen
# from outside) only when `link_only` is set; any other generator expression and CMake's own
# markers (::@...) are dropped.
function(twinraster_linked_targets items link_only out)
  set(targets "")
  foreach(item IN LISTS items)
    if(item MATCHES "^\\$<LINK_ONLY:(.*)>$")
      if(NOT link_only)
        continue()
      endif()
      set(item ${CMAKE_MATCH_1})
    endif()
    if(item MATCHES "^\\$<BUILD_INTERFACE:(.*)>$")
      set(item ${CMAKE_MATCH_1})
    endif()
    if(TARGET ${item})
      list(APPEND targets ${item})
    endif()
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# The stages `target` passes on to what links it: its own, and those of its PUBLIC and INTERFACE
# links, transitively.
function(twinraster_stages_passed_on target source_dir out)
  twinraster_stage_of(${target} ${source_dir} stage)
  set(stages ${stage})
  get_target_property(items ${target} INTERFACE_LINK_LIBRARIES)
  if(items)
    twinraster_linked_targets("${items}" FALSE linked)
    foreach(next IN LISTS linked)
      twinraster_stages_passed_on(${next} ${source_dir} more)
      list(APPEND stages ${more})
    endforeach()
  endif()
  list(REMOVE_DUPLICATES stages)
  set(${out} ${stages} PARENT_SCOPE)
endfunction()

# The targets defined in `dir` and in the folders it adds, at any depth.
function(twinraster_targets_under dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(subdir IN LISTS subdirs)
    twinraster_targets_under(${subdir} more)
    list(APPEND targets ${more})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# The .cpp files `target` compiles, as absolute paths: an option can leave a file of a folder out
# (gpu/'s Vulkan files without Vulkan), and what is not compiled is not checked.
function(twinraster_compiled_sources target out)
  get_target_property(sources ${target} SOURCES)
  get_target_property(dir ${target} SOURCE_DIR)
  set(paths "")
  foreach(source IN LISTS sources)
    if(source MATCHES "\\.cpp$")
      get_filename_component(path ${source} ABSOLUTE BASE_DIR ${dir})
      list(APPEND paths ${path})
    endif()
  endforeach()
  set(${out} ${paths} PARENT_SCOPE)
endfunction()

function(twinraster_write_allowed_layers source_dir file)
  get_property(built DIRECTORY ${source_dir}/src PROPERTY SUBDIRECTORIES)
  set(text "# Written at configure time by tests/allowed_layers.cmake, from the targets' links.\n")
  foreach(dir IN LISTS built)
    get_filename_component(folder ${dir} NAME)
    set(allowed ${folder})
    set(compiled "")
    twinraster_targets_under(${dir} targets)
    foreach(target IN LISTS targets)
      get_target_property(type ${target} TYPE)
      if(type STREQUAL "UTILITY")
        continue()
      endif()
      set(items "")
      if(NOT type STREQUAL "INTERFACE_LIBRARY")
        get_target_property(items ${target} LINK_LIBRARIES)
        twinraster_compiled_sources(${target} sources)
        list(APPEND compiled ${sources})
      endif()
      get_target_property(interface ${target} INTERFACE_LINK_LIBRARIES)
      foreach(which IN ITEMS items interface)
        if(${which})
          twinraster_linked_targets("${${which}}" TRUE linked)
          foreach(next IN LISTS linked)
            twinraster_stages_passed_on(${next} ${source_dir} stages)
            list(APPEND allowed ${stages})
          endforeach()
        endif()
      endforeach()
    endforeach()
    list(REMOVE_DUPLICATES allowed)
    string(APPEND text "set(allowed_${folder} \"${allowed}\")\n")
    string(APPEND text "set(compiled_${folder} \"${compiled}\")\n")
  endforeach()
  file(WRITE ${file} "${text}")
endfunction()
