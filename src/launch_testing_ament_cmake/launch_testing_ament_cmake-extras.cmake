# add_launch_test() for packages that find_package(launch_testing_ament_cmake).
find_package(ament_cmake_test QUIET REQUIRED)
include("${launch_testing_ament_cmake_DIR}/add_launch_test.cmake")
