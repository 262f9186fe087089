# shellcheck shell=bash
# Source this file to get the workspace environment in the current shell:
#     source scripts/env.sh
# It activates .venv, sources install/setup.bash when the workspace is built, and
# sets what the pip-installed ROS 2 needs (see README "Environment").

_ws_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
_ws_venv="$_ws_root/.venv"
_ws_pyver="$("$_ws_venv/bin/python" -c 'import sys; print(f"{sys.version_info[0]}.{sys.version_info[1]}")' 2>/dev/null)"

export VIRTUAL_ENV="$_ws_venv"
case ":$PATH:" in *":$_ws_venv/bin:"*) ;; *) export PATH="$_ws_venv/bin:$PATH" ;; esac

if [ -f "$_ws_root/install/setup.bash" ]; then
  # colcon's scripts read unset variables; relax nounset while they run.
  case $- in *u*) set +u; source "$_ws_root/install/setup.bash"; set -u ;;
             *) source "$_ws_root/install/setup.bash" ;; esac
fi

# The wheels' packages live in the venv prefix: ament_index and CMake look there last.
case ":${AMENT_PREFIX_PATH:-}:" in *":$_ws_venv:"*) ;;
  *) export AMENT_PREFIX_PATH="${AMENT_PREFIX_PATH:+$AMENT_PREFIX_PATH:}$_ws_venv" ;; esac
case ":${CMAKE_PREFIX_PATH:-}:" in *":$_ws_venv:"*) ;;
  *) export CMAKE_PREFIX_PATH="${CMAKE_PREFIX_PATH:+$CMAKE_PREFIX_PATH:}$_ws_venv" ;; esac

# rclpy's wheel would otherwise re-exec every Python process to set LD_LIBRARY_PATH, with
# the venv's libraries in arbitrary order. Set it once here, workspace libraries first, so
# a generated interface library in install/ always wins over anything in the venv.
if [ -z "${_ROS_WHEELS_BOOTSTRAP_COMPLETE:-}" ] && [ -n "$_ws_pyver" ]; then
  _ws_ld="$_ws_venv/lib"
  for _d in "$_ws_venv/lib/python$_ws_pyver/site-packages"/ros_*.libs; do
    [ -d "$_d" ] && _ws_ld="$_ws_ld:$_d"
  done
  export LD_LIBRARY_PATH="${LD_LIBRARY_PATH:+$LD_LIBRARY_PATH:}$_ws_ld"
  export _ROS_WHEELS_BOOTSTRAP_COMPLETE=1
fi

export RMW_IMPLEMENTATION="${RMW_IMPLEMENTATION:-rmw_fastrtps_cpp}"
# What an apt install's ros_environment package sets (ros2 doctor and scripts read them).
export ROS_DISTRO="${ROS_DISTRO:-jazzy}" ROS_VERSION=2 ROS_PYTHON_VERSION=3
# Keep DDS traffic on this machine unless the user deliberately chose otherwise.
export ROS_AUTOMATIC_DISCOVERY_RANGE="${ROS_AUTOMATIC_DISCOVERY_RANGE:-LOCALHOST}"
# Lets a hand-typed `colcon build` pick up the CMake fix for the wheels (scripts/setup writes it).
[ -f "$_ws_venv/colcon-defaults.yaml" ] && export COLCON_DEFAULTS_FILE="$_ws_venv/colcon-defaults.yaml"
# Line-buffered node output, so logs appear at once in pipes and test captures.
export PYTHONUNBUFFERED=1

unset _ws_root _ws_venv _ws_pyver _ws_ld _d
