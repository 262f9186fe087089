# Included from tools/cmake/project_include.cmake at every project() of this workspace, so only
# when the build goes through scripts/setup or .venv/colcon-defaults.yaml; a plain
# `colcon build` on an apt-installed Jazzy never sees it and generates everything.
#
# WS_INTERFACES_FOR=python (a cache variable scripts/setup passes) limits the rosidl generators
# of an interface package to what rclpy loads: the type description, the C structs, the C type
# supports (Fast DDS's serialisation, introspection, the dispatcher) and the Python modules.
# Every node of this workspace is Python, nothing includes a generated C++ header, and the
# four C++ generators were ~half of the interface packages' compile time (docs/speed.md).
# Unset or any other value: every generator, as upstream.
#
# How: rosidl_generate_interfaces() runs the generators registered for the ament extension
# point `rosidl_generate_idl_interfaces` (ament_execute_extensions); each generator registers
# itself when rosidl_default_generators is found. This file finds it first (its config file
# is guarded against a second inclusion, so the package's own find_package() keeps this
# state) and drops the C++ generators from that list. No interface package's CMakeLists.txt
# changes: a package that build-depends on rosidl_default_generators is limited.
set(WS_INTERFACES_FOR "" CACHE STRING
  "'python': generate only what rclpy uses (C and Python); empty: every rosidl generator")

function(_ws_uses_rosidl result)
  set(${result} FALSE PARENT_SCOPE)
  if(EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/package.xml")
    file(STRINGS "${CMAKE_CURRENT_SOURCE_DIR}/package.xml" _lines
      REGEX "<(buildtool_depend|build_depend|depend)>rosidl_default_generators<")
    if(_lines)
      set(${result} TRUE PARENT_SCOPE)
    endif()
  endif()
endfunction()

if(WS_INTERFACES_FOR STREQUAL "python" AND CMAKE_CURRENT_SOURCE_DIR STREQUAL CMAKE_SOURCE_DIR)
  _ws_uses_rosidl(_ws_rosidl)
  if(_ws_rosidl)
    find_package(rosidl_default_generators REQUIRED)
    set(_ws_extensions "${AMENT_EXTENSIONS_rosidl_generate_idl_interfaces}")
    list(FILTER AMENT_EXTENSIONS_rosidl_generate_idl_interfaces EXCLUDE REGEX
      "^(rosidl_generator_cpp|rosidl_typesupport_cpp|rosidl_typesupport_fastrtps_cpp|rosidl_typesupport_introspection_cpp):")
    message(STATUS "WS_INTERFACES_FOR=python: rosidl generators "
      "${AMENT_EXTENSIONS_rosidl_generate_idl_interfaces}")
  endif()
endif()
