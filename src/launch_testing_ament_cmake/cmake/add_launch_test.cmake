# add_launch_test(<file> [TARGET <name>] [TIMEOUT <seconds>] [PYTHON_EXECUTABLE <python>]
#                 [ARGS <launch arguments>...] [ENV ...] [APPEND_ENV ...]
#                 [APPEND_LIBRARY_DIRS ...])
#
# Runs `python -m launch_testing.launch_test <file> --junit-xml=<result> --package-name=<project>`
# as a ctest test (ament_add_test), so `colcon test` runs it and `colcon test-result` reads
# its JUnit XML, as upstream's launch_testing_ament_cmake does.
function(add_launch_test file)
  cmake_parse_arguments(_launch_test "" "TARGET;TIMEOUT;PYTHON_EXECUTABLE"
    "ARGS;ENV;APPEND_ENV;APPEND_LIBRARY_DIRS" ${ARGN})
  if(_launch_test_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "add_launch_test() called with unused arguments: "
      "${_launch_test_UNPARSED_ARGUMENTS}")
  endif()
  if(IS_ABSOLUTE "${file}")
    set(_file "${file}")
  else()
    set(_file "${CMAKE_CURRENT_SOURCE_DIR}/${file}")
  endif()
  if(NOT EXISTS "${_file}")
    message(FATAL_ERROR "add_launch_test() could not find the launch test file '${_file}'")
  endif()
  if(NOT _launch_test_TARGET)
    get_filename_component(_launch_test_TARGET "${_file}" NAME_WE)
  endif()
  if(NOT _launch_test_TIMEOUT)
    set(_launch_test_TIMEOUT 60)
  endif()
  if(NOT _launch_test_PYTHON_EXECUTABLE)
    if(Python3_EXECUTABLE)
      set(_launch_test_PYTHON_EXECUTABLE "${Python3_EXECUTABLE}")
    else()
      find_package(Python3 REQUIRED COMPONENTS Interpreter)
      set(_launch_test_PYTHON_EXECUTABLE "${Python3_EXECUTABLE}")
    endif()
  endif()
  set(_result "${AMENT_TEST_RESULTS_DIR}/${PROJECT_NAME}/${_launch_test_TARGET}.xml")
  set(_command "${_launch_test_PYTHON_EXECUTABLE}" "-m" "launch_testing.launch_test"
    "${_file}" "--junit-xml=${_result}" "--package-name=${PROJECT_NAME}"
    ${_launch_test_ARGS})
  ament_add_test("${_launch_test_TARGET}"
    COMMAND ${_command}
    OUTPUT_FILE "${CMAKE_BINARY_DIR}/launch_test/${_launch_test_TARGET}.txt"
    RESULT_FILE "${_result}"
    TIMEOUT "${_launch_test_TIMEOUT}"
    ENV ${_launch_test_ENV}
    APPEND_ENV ${_launch_test_APPEND_ENV}
    APPEND_LIBRARY_DIRS ${_launch_test_APPEND_LIBRARY_DIRS})
endfunction()
