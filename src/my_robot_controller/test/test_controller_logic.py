"""turtle_controller's decisions as plain functions: no ROS graph, no processes."""

import pytest
from my_robot_controller.turtle_logic import (
    CANVAS_SIZE,
    DEFAULTS,
    PARAMETERS,
    ControllerConfig,
    Side,
    check_parameters,
    colour_for,
    colour_name,
    near_wall,
    pen_call_due,
    side_of,
    velocity_for,
    with_changes,
)


@pytest.mark.parametrize('x, side', [
    (0.0, Side.LEFT), (5.49, Side.LEFT), (5.4999999, Side.LEFT),
    (5.5, Side.RIGHT), (5.51, Side.RIGHT), (CANVAS_SIZE, Side.RIGHT),
])
def test_side_of_splits_at_boundary(x, side):
    assert side_of(x, 5.5) is side


@pytest.mark.parametrize('x, y, expected', [
    (5.5, 5.5, (5.0, 0.0)),        # open field: straight and fast
    (2.0, 9.0, (5.0, 0.0)),        # exactly on the margins still counts as open field
    (1.99, 5.5, (1.0, 0.9)),       # each of the four walls: slow and turn
    (9.01, 5.5, (1.0, 0.9)),
    (5.5, 1.99, (1.0, 0.9)),
    (5.5, 9.01, (1.0, 0.9)),
    (0.0, 0.0, (1.0, 0.9)),        # a corner
])
def test_velocity_for_pose(x, y, expected):
    assert velocity_for(x, y, DEFAULTS) == expected
    assert near_wall(x, y, DEFAULTS) == (expected == (1.0, 0.9))


def test_velocity_uses_configured_speeds_and_margins():
    config = with_changes(DEFAULTS, {'cruise_speed': 3, 'wall_speed': 0.5, 'wall_turn_rate': -1.2,
                                     'wall_margin_low': 1.0, 'wall_margin_high': 10.0})
    assert velocity_for(1.5, 5.0, config) == (3.0, 0.0)
    assert velocity_for(0.5, 5.0, config) == (0.5, -1.2)


def test_default_colours_width_and_names():
    assert colour_for(Side.LEFT, DEFAULTS) == (255, 0, 0)
    assert colour_for(Side.RIGHT, DEFAULTS) == (0, 255, 0)
    assert DEFAULTS.pen_width == 3
    assert colour_name((255, 0, 0)) == 'red (255, 0, 0)'
    assert colour_name((12, 34, 56)) == '(12, 34, 56)'


def test_pen_call_only_when_side_changes():
    # Replays a pose stream and counts the calls the controller would make.
    xs = [5.54, 5.6, 5.7, 5.4, 5.3, 5.3, 5.49, 5.5, 7.0, 7.0, 2.0]
    requested, calls = None, []
    for x in xs:
        current = side_of(x, 5.5)
        if pen_call_due(requested, current):
            calls.append(current)
            requested = current
    assert calls == [Side.RIGHT, Side.LEFT, Side.RIGHT, Side.LEFT]


def test_pen_call_before_first_pose_and_after_forgetting():
    assert not pen_call_due(None, None)            # no pose yet: no side to colour
    assert not pen_call_due(Side.LEFT, Side.LEFT)
    assert pen_call_due(None, Side.LEFT)           # pen forgotten (new turtle...): ask again
    assert pen_call_due(Side.RIGHT, Side.LEFT)


def test_defaults_are_valid_and_match_the_table():
    assert check_parameters(DEFAULTS) == []
    assert DEFAULTS == ControllerConfig(boundary_x=5.5, left_r=255, left_g=0, left_b=0,
                                        right_r=0, right_g=255, right_b=0, pen_width=3,
                                        wall_margin_low=2.0, wall_margin_high=9.0,
                                        cruise_speed=5.0, wall_speed=1.0, wall_turn_rate=0.9)
    assert set(PARAMETERS) == set(DEFAULTS.__dataclass_fields__)


@pytest.mark.parametrize('changes, message', [
    ({'left_r': 300}, "parameter 'left_r' = 300 is out of range: must be an integer in [0, 255]"),
    ({'right_b': -1}, "parameter 'right_b' = -1 is out of range: must be an integer in [0, 255]"),
    ({'pen_width': 0}, "parameter 'pen_width' = 0 is out of range: must be an integer in [1, 255]"),
    ({'pen_width': 256}, "'pen_width' = 256 is out of range: must be an integer in [1, 255]"),
    ({'cruise_speed': -1.0}, "'cruise_speed' = -1.0 is out of range: must be a number in [0, 20]"),
    ({'wall_speed': -0.1}, "'wall_speed' = -0.1 is out of range: must be a number in [0, 20]"),
    ({'boundary_x': 11.2}, "'boundary_x' = 11.2 is out of range: must be a number in [0, 11.0889]"),
    ({'boundary_x': -0.5}, "'boundary_x' = -0.5 is out of range"),
    ({'wall_margin_low': 9.0}, "'wall_margin_low' = 9.0 must be below 'wall_margin_high' = 9.0"),
    ({'wall_margin_high': 1.0},
     "'wall_margin_low' = 2.0 must be below 'wall_margin_high' = 1.0"),
    ({'left_g': 'abc'}, "parameter 'left_g' must be an integer in [0, 255], got 'abc' (str)"),
    ({'left_g': 2.5}, "parameter 'left_g' must be an integer in [0, 255], got 2.5 (float)"),
    ({'wall_speed': True}, "'wall_speed' must be a number in [0, 20], got True (bool)"),
])
def test_bad_parameters_are_named_with_their_range(changes, message):
    problems = check_parameters(with_changes(DEFAULTS, changes))
    assert len(problems) == 1
    assert message in problems[0]


@pytest.mark.parametrize('changes', [
    {'left_r': 0, 'left_g': 255, 'pen_width': 1},
    {'pen_width': 255, 'boundary_x': 0.0, 'cruise_speed': 0.0},
    {'boundary_x': CANVAS_SIZE, 'wall_margin_low': 0.0, 'wall_margin_high': CANVAS_SIZE},
    {'wall_turn_rate': -10.0, 'cruise_speed': 20},
])
def test_edge_values_are_accepted(changes):
    assert check_parameters(with_changes(DEFAULTS, changes)) == []


def test_integers_become_floats_for_float_parameters():
    config = with_changes(DEFAULTS, {'boundary_x': 6, 'left_r': 7})
    assert config.boundary_x == 6.0 and isinstance(config.boundary_x, float)
    assert config.left_r == 7 and isinstance(config.left_r, int)
