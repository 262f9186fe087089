# A skipped test, with the reason, for each linter whose program is missing; only where that
# linter would have run (C/C++ files present), as its own hook decides.
file(GLOB_RECURSE _ament_lint_common_sources FOLLOW_SYMLINKS
  "*.c" "*.cc" "*.cpp" "*.cxx" "*.h" "*.hh" "*.hpp" "*.hxx")
if(_ament_lint_common_sources)
  find_program(_ament_lint_common_skip_bin NAMES "ament_lint_skip")
  if(NOT _ament_lint_common_skip_bin)
    message(FATAL_ERROR "ament_lint_common could not find program 'ament_lint_skip'")
  endif()
  foreach(_tool ${_ament_lint_common_missing})
    set(_result "${AMENT_TEST_RESULTS_DIR}/${PROJECT_NAME}/${_tool}.xunit.xml")
    set(_reason "the '${_tool}' program is not installed (apt-get install ${_tool})")
    message(STATUS "Added test '${_tool}', reported as skipped: ${_reason}")
    ament_add_test("${_tool}"
      COMMAND "${_ament_lint_common_skip_bin}" --xunit-file "${_result}" --reason "${_reason}"
      OUTPUT_FILE "${CMAKE_BINARY_DIR}/ament_lint_common/${_tool}.txt"
      RESULT_FILE "${_result}"
      WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}")
    set_tests_properties("${_tool}" PROPERTIES LABELS "${_tool};linter")
  endforeach()
endif()
