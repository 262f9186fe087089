find_package(ament_cmake_test QUIET REQUIRED)

include("${ament_cmake_copyright_DIR}/ament_copyright.cmake")

ament_register_extension("ament_lint_auto" "ament_cmake_copyright" "ament_cmake_copyright_lint_hook.cmake")
