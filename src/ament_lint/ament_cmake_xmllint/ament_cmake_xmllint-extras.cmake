find_package(ament_cmake_test QUIET REQUIRED)

include("${ament_cmake_xmllint_DIR}/ament_xmllint.cmake")

ament_register_extension("ament_lint_auto" "ament_cmake_xmllint" "ament_cmake_xmllint_lint_hook.cmake")
