""""Monitoring for parameter changes (Python)" (Jazzy), typed as the page says: a package made
by `ros2 pkg create`, the page's node with rclpy's ParameterEventHandler (its own parameter,
then also parameter_blackboard's), the entry point, `colcon build --packages-select`; then
`ros2 param set` on both nodes shows the page's log lines.
"""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from ws_testing import colcon_workspace

# The page's node, with section 3.1's second callback (parameter_blackboard's parameter).
NODE = Path(__file__).parents[1] / 'data' / 'parameter_event_handler' / 'parameter_event_handler.py'
ENTRY_POINT = ("            'node_with_parameters = "
               "python_parameter_event_handler.parameter_event_handler:main',\n")


@pytest.fixture(scope='module')
def workspace(tmp_path_factory) -> Path:
    with colcon_workspace(tmp_path_factory) as ws:
        package = ws.create('python_parameter_event_handler', '--build-type', 'ament_python',
                            '--license', 'Apache-2.0', '--dependencies', 'rclpy')
        shutil.copy(NODE, package / 'python_parameter_event_handler')
        setup = (package / 'setup.py').read_text()
        assert "'console_scripts': [\n" in setup, setup
        (package / 'setup.py').write_text(setup.replace("'console_scripts': [\n",
                                                        "'console_scripts': [\n" + ENTRY_POINT))
        ws.build('--packages-select', 'python_parameter_event_handler', timeout=240)
    return ws.root


def test_the_pages_callbacks(workspace, ros_env, launch) -> None:
    source = f'. {workspace}/install/setup.bash && '
    node = launch(argv=['bash', '-c', source + 'exec ros2 run python_parameter_event_handler '
                        'node_with_parameters'])
    blackboard = launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'parameter_blackboard'])
    blackboard.wait_for_output(
        r"^\[INFO\] \[[\d.]+\] \[parameter_blackboard\]: Parameter blackboard node named "
        r"'/parameter_blackboard' ready, and serving '\d+' parameters already!$", timeout=20)

    def param_set(*args: str) -> str:
        return subprocess.run(['bash', '-c', source + 'ros2 param set ' + ' '.join(args)],
                              env=ros_env, capture_output=True, text=True, timeout=60).stdout

    assert param_set('node_with_parameters', 'an_int_param', '43') == \
        'Set parameter successful\n'
    node.wait_for_output(r'^\[INFO\] \[[\d.]+\] \[node_with_parameters\]: Received an update to '
                         r'parameter: an_int_param: 43$', timeout=20)
    assert param_set('parameter_blackboard', 'a_double_param', '3.45') == \
        'Set parameter successful\n'
    node.wait_for_output(r'^\[INFO\] \[[\d.]+\] \[node_with_parameters\]: Received an update to '
                         r'parameter: a_double_param: 3\.45$', timeout=20)
    assert len(re.findall('Received an update', node.output)) == 2
    assert blackboard.stop() == 0
