"""The tf2 Python pages' `rosdep install -i --from-path src --rosdistro jazzy -y` as written:
their learning_tf2_py package.xml names `tf2_ros_py` (upstream's package of the Python tf2_ros
module) and the other packages the pages use; every key resolves, nothing is left to install.
"""
from __future__ import annotations

import subprocess

from support import run_checked

PAGE_DEPENDS = ['geometry_msgs', 'python3-numpy', 'rclpy', 'tf2_ros_py', 'tf2_ros',
                'tf2_geometry_msgs', 'tf2_msgs', 'turtlesim']


def test_learning_tf2_py_rosdep_install_as_the_pages_type_it(tmp_path, ros_env) -> None:
    env = dict(ros_env, ROSDEP_WORKSPACE_STATE=str(tmp_path / 'rosdep'))
    src = tmp_path / 'src'
    src.mkdir()
    run_checked(['ros2', 'pkg', 'create', '--build-type', 'ament_python', '--license',
                 'Apache-2.0', '--', 'learning_tf2_py'], src, env)
    xml = src / 'learning_tf2_py' / 'package.xml'
    xml.write_text(xml.read_text().replace('  <test_depend>', ''.join(
        f'  <exec_depend>{key}</exec_depend>\n' for key in PAGE_DEPENDS) + '  <test_depend>', 1))
    for command in (['init'], ['update']):
        ran = subprocess.run(['rosdep', *command], cwd=tmp_path, env=env, capture_output=True,
                             text=True, timeout=60, stdin=subprocess.DEVNULL)
        assert ran.returncode == 0, ran.stdout + ran.stderr
    install = subprocess.run(['rosdep', 'install', '-i', '--from-path', 'src', '--rosdistro',
                              'jazzy', '-y'], cwd=tmp_path, env=env, capture_output=True,
                             text=True, timeout=60, stdin=subprocess.DEVNULL)
    assert install.returncode == 0, install.stdout + install.stderr
    assert install.stdout == '#All required rosdeps installed successfully\n'
