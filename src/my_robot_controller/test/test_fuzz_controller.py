"""Generated parameter sets for turtle_controller (Hypothesis): answered, refused with the
parameter's name and what is allowed, nothing changed when refused, the node still driving."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st
from rcl_interfaces.msg import Parameter, ParameterType
from rcl_interfaces.srv import GetParameters, SetParameters

from ws_testing import RosProcess, TestNode, executable, leased_domain, ros_environment
from ws_testing.fuzz import CI, Target, describe, names, parameter_values

# name -> (integer?, low, high), as documented in docs/controller.md
RANGES = {
    'boundary_x': (False, 0.0, 11.088889122009277),
    'left_r': (True, 0, 255), 'left_g': (True, 0, 255), 'left_b': (True, 0, 255),
    'right_r': (True, 0, 255), 'right_g': (True, 0, 255), 'right_b': (True, 0, 255),
    'pen_width': (True, 1, 255),
    'wall_margin_low': (False, 0.0, 11.088889122009277),
    'wall_margin_high': (False, 0.0, 11.088889122009277),
    'cruise_speed': (False, 0.0, 20.0), 'wall_speed': (False, 0.0, 20.0),
    'wall_turn_rate': (False, -10.0, 10.0),
}


def allowed(name: str, kind: int, value, current: dict[str, float]) -> bool:
    """Whether the controller must accept `name` := `value` given the current values."""
    if name not in RANGES:
        return False
    integer, low, high = RANGES[name]
    if kind == ParameterType.PARAMETER_INTEGER:
        number = value
    elif kind == ParameterType.PARAMETER_DOUBLE and not integer:
        number = value
    else:
        return False
    if not (isinstance(number, int) or math.isfinite(number)) or not low <= number <= high:
        return False
    margins = dict(current, **{name: number})
    return margins['wall_margin_low'] < margins['wall_margin_high']


@pytest.fixture(scope='module')
def controller(tmp_path_factory):
    tmp = tmp_path_factory.mktemp('fuzz-controller')
    with leased_domain() as domain:
        process = RosProcess([executable('my_robot_controller', 'turtle_controller')],
                             ros_environment(domain), tmp / 'controller.log')
        probe = TestNode(domain)
        try:
            process.wait_for_output(r'driving turtle1', timeout=20)
            yield Target(process, probe)
        finally:
            probe.close()
            assert process.stop() == 0, process.output[-3000:]
            assert 'Traceback' not in process.output, process.output[-3000:]


def test_parameter_sets(controller):
    names_all = list(RANGES)
    get = GetParameters.Request(names=names_all)

    def current() -> list:
        return controller.call(GetParameters, '/turtle_controller/get_parameters', get).values

    @CI
    @given(name=st.one_of(st.sampled_from(names_all), names), value=parameter_values())
    def check(name, value):
        before = current()
        values = {n: describe(v)[1] for n, v in zip(names_all, before, strict=True)}
        result = controller.call(SetParameters, '/turtle_controller/set_parameters',
                                 SetParameters.Request(parameters=[Parameter(name=name,
                                                                             value=value)]))
        kind, given_value = describe(value)
        expected = allowed(name, kind, given_value, values)
        assert result.results[0].successful == expected, (name, value, result)
        after = current()
        if expected and name in RANGES:
            index = names_all.index(name)
            assert describe(after[index])[1] == given_value
        else:
            assert result.results[0].reason
            assert repr(name) in result.results[0].reason or name in result.results[0].reason
            assert [describe(v) for v in after] == [describe(v) for v in before]

    check()
    controller.assert_alive()
