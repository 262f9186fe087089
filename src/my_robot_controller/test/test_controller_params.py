"""turtle_controller refuses bad parameters, at start-up and at runtime, and changes nothing."""

import pytest
from rcl_interfaces.msg import Parameter, ParameterType, ParameterValue
from rcl_interfaces.srv import DescribeParameters, GetParameters, SetParameters

CONTROLLER = ('my_robot_controller', 'turtle_controller')


@pytest.mark.parametrize('overrides, message', [
    (['left_r:=300'], "parameter 'left_r' = 300 is out of range: must be an integer in [0, 255]"),
    (['pen_width:=0'], "parameter 'pen_width' = 0 is out of range: must be an integer in [1, 255]"),
    (['pen_width:=256'],
     "parameter 'pen_width' = 256 is out of range: must be an integer in [1, 255]"),
    (['cruise_speed:=-1.0'],
     "parameter 'cruise_speed' = -1.0 is out of range: must be a number in [0, 20]"),
    (['boundary_x:=11.5'],
     "parameter 'boundary_x' = 11.5 is out of range: must be a number in [0, 11.0889]"),
    (['wall_margin_low:=9.0'],
     "parameter 'wall_margin_low' = 9.0 must be below 'wall_margin_high' = 9.0"),
    (['right_g:=green'], "parameter 'right_g' must be an integer in [0, 255], got 'green' (str)"),
])
def test_bad_start_parameters_exit_with_a_clear_error(launch, overrides, message):
    args = ['--ros-args'] + [arg for o in overrides for arg in ('-p', o)]
    controller = launch(*CONTROLLER, *args)
    assert controller.wait() == 2, controller.output
    assert f'turtle_controller: error: {message}' in controller.output
    assert 'Traceback' not in controller.output
    assert 'driving turtle1' not in controller.output


def _value(value):
    if isinstance(value, float):
        return ParameterValue(type=ParameterType.PARAMETER_DOUBLE, double_value=value)
    return ParameterValue(type=ParameterType.PARAMETER_INTEGER, integer_value=value)


def _plain(value: ParameterValue):
    return value.integer_value if value.type == ParameterType.PARAMETER_INTEGER \
        else value.double_value


@pytest.fixture
def controller(launch):
    process = launch(*CONTROLLER, '--ros-args', '-p', 'boundary_x:=6')
    process.wait_for_output(r'driving turtle1: pen red \(255, 0, 0\) for x < 6, green')
    return process


NAMES = ['boundary_x', 'left_r', 'right_g', 'pen_width', 'wall_margin_low', 'wall_margin_high',
         'cruise_speed', 'wall_speed', 'wall_turn_rate']


def test_bad_runtime_parameters_are_refused_and_nothing_changes(controller, probe):
    def current():
        response = probe.call(GetParameters, '/turtle_controller/get_parameters',
                              GetParameters.Request(names=NAMES))
        return dict(zip(NAMES, map(_plain, response.values), strict=True))

    def set_one(name, value):
        request = SetParameters.Request(parameters=[Parameter(name=name, value=_value(value))])
        response = probe.call(SetParameters, '/turtle_controller/set_parameters', request)
        return response.results[0]

    before = current()
    # An integer start value for a float parameter was taken as that number.
    assert before == {'boundary_x': 6.0, 'left_r': 255, 'right_g': 255, 'pen_width': 3,
                      'wall_margin_low': 2.0, 'wall_margin_high': 9.0, 'cruise_speed': 5.0,
                      'wall_speed': 1.0, 'wall_turn_rate': 0.9}
    refused = {
        ('left_r', 300): ('left_r', 'Min: 0, Max: 255'),
        ('pen_width', 0): ('pen_width', 'Min: 1, Max: 255'),
        ('pen_width', 256): ('pen_width', 'Min: 1, Max: 255'),
        ('cruise_speed', -1.0): ('cruise_speed', 'Min: 0.0, Max: 20.0'),
        ('boundary_x', 11.2): ('boundary_x', 'Min: 0.0, Max: 11.08888'),
        ('wall_margin_low', 9.5): ("'wall_margin_low' = 9.5 must be below "
                                   "'wall_margin_high' = 9.0", ''),
        ('wall_margin_high', 1.5): ("'wall_margin_low' = 2.0 must be below "
                                    "'wall_margin_high' = 1.5", ''),
    }
    for (name, value), (names_it, allowed) in refused.items():
        result = set_one(name, value)
        assert not result.successful, (name, value)
        assert names_it in result.reason and allowed in result.reason, result.reason
    assert current() == before
    assert 'parameters changed' not in controller.output

    # Valid changes go through (an integer for a float parameter too) and are logged.
    assert set_one('wall_margin_low', 1.5).successful
    assert set_one('boundary_x', 4).successful
    after = current()
    assert (after['wall_margin_low'], after['boundary_x']) == (1.5, 4.0)
    controller.wait_for_output(r'parameters changed: boundary_x=4\.0')


def test_parameters_are_described_with_their_ranges(controller, probe):
    response = probe.call(DescribeParameters, '/turtle_controller/describe_parameters',
                          DescribeParameters.Request(names=['left_g', 'pen_width', 'boundary_x']))
    left_g, width, boundary = response.descriptors
    assert (left_g.integer_range[0].from_value, left_g.integer_range[0].to_value) == (0, 255)
    assert (width.integer_range[0].from_value, width.integer_range[0].to_value) == (1, 255)
    assert boundary.floating_point_range[0].from_value == 0.0
    assert boundary.floating_point_range[0].to_value == pytest.approx(11.0889, abs=1e-4)
    assert 'green channel' in left_g.description
