# ament_copyright([TESTNAME name] [TIMEOUT s] [EXCLUDE files...] [paths...]): add a test running the
# 'ament_copyright' program on the package's source directory, with an xunit result file.
function(ament_copyright)
  cmake_parse_arguments(ARG "" "TESTNAME;TIMEOUT" "EXCLUDE" ${ARGN})
  if(NOT ARG_TESTNAME)
    set(ARG_TESTNAME "copyright")
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 120)
  endif()
  find_program(ament_copyright_BIN NAMES "ament_copyright")
  if(NOT ament_copyright_BIN)
    message(FATAL_ERROR "ament_copyright() could not find program 'ament_copyright'")
  endif()
  set(result_file "${AMENT_TEST_RESULTS_DIR}/${PROJECT_NAME}/${ARG_TESTNAME}.xunit.xml")
  set(cmd "${ament_copyright_BIN}" "--xunit-file" "${result_file}")
  if(ARG_EXCLUDE)
    list(APPEND cmd "--exclude" ${ARG_EXCLUDE})
  endif()
  list(APPEND cmd ${ARG_UNPARSED_ARGUMENTS})
  file(MAKE_DIRECTORY "${CMAKE_BINARY_DIR}/ament_copyright")
  ament_add_test(
    "${ARG_TESTNAME}"
    COMMAND ${cmd}
    OUTPUT_FILE "${CMAKE_BINARY_DIR}/ament_copyright/${ARG_TESTNAME}.txt"
    RESULT_FILE "${result_file}"
    WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
    TIMEOUT "${ARG_TIMEOUT}"
  )
  set_tests_properties("${ARG_TESTNAME}" PROPERTIES LABELS "copyright;linter")
endfunction()
