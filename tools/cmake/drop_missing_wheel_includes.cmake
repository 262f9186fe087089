# Injected into every CMake package of this workspace through CMAKE_PROJECT_INCLUDE
# (see scripts/env.sh); an apt-installed ROS never sees it.
#
# Some pip wheels of ROS 2 Jazzy export *__rosidl_generator_py targets whose
# INTERFACE_INCLUDE_DIRECTORIES still name the wheel build machine's Python
# (/opt/python/cp311-cp311/include/python3.11). CMake refuses to generate with a
# non-existent include path, so once the directory is fully configured we drop
# every such path from the imported targets; targets with valid paths are untouched.

function(_turtle_ws_drop_missing_includes)
  get_property(_targets DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" PROPERTY IMPORTED_TARGETS)
  foreach(_target IN LISTS _targets)
    get_target_property(_dirs "${_target}" INTERFACE_INCLUDE_DIRECTORIES)
    if(NOT _dirs)
      continue()
    endif()
    set(_kept "")
    foreach(_dir IN LISTS _dirs)
      if(_dir MATCHES "^\\$<" OR EXISTS "${_dir}")
        list(APPEND _kept "${_dir}")
      endif()
    endforeach()
    if(NOT _kept STREQUAL _dirs)
      set_target_properties("${_target}" PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_kept}")
    endif()
  endforeach()
endfunction()

if(CMAKE_CURRENT_SOURCE_DIR STREQUAL CMAKE_SOURCE_DIR)
  cmake_language(DEFER DIRECTORY "${CMAKE_SOURCE_DIR}" CALL _turtle_ws_drop_missing_includes)
endif()
