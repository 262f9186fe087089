# Find every <test_depend> of the package; each linter package found registers its
# "ament_lint_auto" hook, and ament_package() then runs those hooks (adding the tests).
# A package already marked <name>_FOUND (e.g. set(ament_cmake_copyright_FOUND TRUE))
# is skipped, which is how a package opts out of one linter.
macro(ament_lint_auto_find_test_dependencies)
  if(NOT "${ARGN}" STREQUAL "")
    message(FATAL_ERROR
      "ament_lint_auto_find_test_dependencies() takes no arguments, got: ${ARGN}")
  endif()
  if(NOT _AMENT_PACKAGE_NAME)
    ament_package_xml()
  endif()
  foreach(_ament_lint_auto_dep ${${PROJECT_NAME}_TEST_DEPENDS})
    find_package(${_ament_lint_auto_dep} QUIET)
    if(${_ament_lint_auto_dep}_FOUND)
      list(APPEND ${PROJECT_NAME}_FOUND_TEST_DEPENDS ${_ament_lint_auto_dep})
    endif()
  endforeach()
endmacro()
