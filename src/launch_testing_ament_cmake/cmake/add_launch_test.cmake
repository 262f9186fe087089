# add_launch_test(<file> [TARGET <name>] [TIMEOUT <seconds>] [PYTHON_EXECUTABLE <python>]
#                 [ARGS <launch arguments>...] [LABELS <label>...]
#                 [<any ament_add_test() option>...])
#
# Runs `python -m launch_testing.launch_test <file> <ARGS> --junit-xml=<result>
# --package-name=<project>` as a ctest test (ament_add_test), so `colcon test` runs it and
# `colcon test-result` reads its JUnit XML, as Jazzy's launch_testing_ament_cmake does:
# - TARGET defaults to the file's path under the project's source (or binary) folder with
#   '/' made '_' (test/test_x.py -> test_test_x.py), so two files of one name in different
#   folders stay two tests;
# - LABELS defaults to `launch_test` (`colcon test --ctest-args -L launch_test`);
# - every other argument goes on to ament_add_test: RUNNER (e.g. ament_cmake_ros's
#   run_test_isolated.py, which gives each test a ROS domain of its own unless ROS_DOMAIN_ID
#   is set), ENV, APPEND_ENV, APPEND_LIBRARY_DIRS, WORKING_DIRECTORY, SKIP_TEST, ...
function(add_launch_test file)
  file(TO_CMAKE_PATH "${file}" file)
  cmake_parse_arguments(_launch_test "" "TARGET;TIMEOUT;PYTHON_EXECUTABLE" "ARGS;LABELS"
    ${ARGN})
  if(IS_ABSOLUTE "${file}")
    set(_file "${file}")
  else()
    set(_file "${CMAKE_CURRENT_SOURCE_DIR}/${file}")
  endif()
  if(NOT EXISTS "${_file}")
    message(FATAL_ERROR "Can't find launch test file \"${file}\"")
  endif()
  if(NOT _launch_test_TARGET)
    _launch_test_name_from_path(_launch_test_TARGET "${_file}")
  endif()
  if(NOT _launch_test_TIMEOUT)
    set(_launch_test_TIMEOUT 60)
  endif()
  if(NOT _launch_test_LABELS)
    set(_launch_test_LABELS "launch_test")
  endif()
  if(NOT _launch_test_PYTHON_EXECUTABLE)
    if(NOT Python3_EXECUTABLE)
      find_package(Python3 REQUIRED COMPONENTS Interpreter)
    endif()
    set(_launch_test_PYTHON_EXECUTABLE "${Python3_EXECUTABLE}")
  endif()
  set(_result "${AMENT_TEST_RESULTS_DIR}/${PROJECT_NAME}/${_launch_test_TARGET}.xunit.xml")
  ament_add_test("${_launch_test_TARGET}"
    COMMAND "${_launch_test_PYTHON_EXECUTABLE}" "-m" "launch_testing.launch_test" "${_file}"
      ${_launch_test_ARGS} "--junit-xml=${_result}" "--package-name=${PROJECT_NAME}"
    OUTPUT_FILE "${CMAKE_BINARY_DIR}/launch_test/${_launch_test_TARGET}.txt"
    RESULT_FILE "${_result}"
    TIMEOUT "${_launch_test_TIMEOUT}"
    ${_launch_test_UNPARSED_ARGUMENTS})
  set_tests_properties("${_launch_test_TARGET}" PROPERTIES LABELS "${_launch_test_LABELS}")
endfunction()

# The test name rostest would give: the path without the project's source or binary folder.
function(_launch_test_name_from_path out path)
  set(_name "${path}")
  foreach(_prefix "${PROJECT_SOURCE_DIR}/" "${PROJECT_BINARY_DIR}/")
    string(LENGTH "${_prefix}" _length)
    string(SUBSTRING "${_name}" 0 ${_length} _start)
    if(_start STREQUAL _prefix)
      string(SUBSTRING "${_name}" ${_length} -1 _name)
    endif()
  endforeach()
  string(REPLACE "/" "_" _name "${_name}")
  set(${out} "${_name}" PARENT_SCOPE)
endfunction()
