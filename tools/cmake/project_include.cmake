# CMAKE_PROJECT_INCLUDE of every CMake package built through scripts/setup or
# .venv/colcon-defaults.yaml (included at the end of each project()); an apt-installed ROS
# never sees it.
include("${CMAKE_CURRENT_LIST_DIR}/drop_missing_wheel_includes.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/interface_generators.cmake")
