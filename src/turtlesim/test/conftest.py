"""Fixtures of turtlesim's node tests: one turtlesim per test module (start-up and discovery
cost seconds), reset to its start state for each test."""

from __future__ import annotations

import pytest
from headless_turtlesim import BACKGROUND, Sim, int_value
from rcl_interfaces.msg import ParameterType, ParameterValue
from std_srvs.srv import Empty

from ws_testing import RosProcess, TestNode, executable, leased_domain, ros_environment


@pytest.fixture(scope='module')
def module_sim(tmp_path_factory):
    tmp = tmp_path_factory.mktemp('turtlesim')
    with leased_domain() as domain:
        process = RosProcess(
            [executable('turtlesim', 'turtlesim_node'), '--headless',
             '--canvas-png', str(tmp / 'c.png'), '--service-introspection', 'metadata'],
            ros_environment(domain), tmp / 'turtlesim.log')
        probe = TestNode(domain)
        try:
            process.wait_for_output(r'Spawning turtle \[turtle1\]')
            yield Sim(process, probe, tmp / 'c.png')
        finally:
            probe.close()
            assert process.stop() == 0, process.output
            assert 'Traceback' not in process.output, process.output


@pytest.fixture
def ts(module_sim):
    """The module's turtlesim, reset to its start state for this test."""
    module_sim.mark = len(module_sim.process.output)
    module_sim.call(Empty, '/reset')
    for name, value in zip(('background_r', 'background_g', 'background_b'), BACKGROUND,
                           strict=True):
        assert module_sim.set_parameter(name, int_value(value)).successful
    module_sim.set_parameter('holonomic', ParameterValue(
        type=ParameterType.PARAMETER_BOOL, bool_value=False))
    module_sim.wait_for_log(r'Resetting turtlesim\.')
    yield module_sim
    module_sim.cleanup()
    assert module_sim.process.popen.poll() is None, module_sim.new_output()

