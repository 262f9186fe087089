find_package(ament_cmake_test QUIET REQUIRED)

include("${ament_cmake_lint_cmake_DIR}/ament_lint_cmake.cmake")

ament_register_extension("ament_lint_auto" "ament_cmake_lint_cmake" "ament_cmake_lint_cmake_lint_hook.cmake")
