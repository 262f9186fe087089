"""Pure decision logic of turtle_controller: no ROS imports, so it is unit-tested directly.

Which side of the boundary the turtle is on, which velocity a pose calls for, which pen a
side wants, whether a set_pen call is due, and the parameter table with its allowed ranges.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace
from enum import Enum

# turtlesim's canvas is (500 - 1) px / 45 px per m wide and high (float32, as upstream).
CANVAS_SIZE = 11.088889122009277


class Side(Enum):
    LEFT = 'left'
    RIGHT = 'right'


Rgb = tuple[int, int, int]

# Names for the log line; any other colour is logged by its numbers alone.
COLOUR_NAMES: dict[Rgb, str] = {
    (255, 0, 0): 'red', (0, 255, 0): 'green', (0, 0, 255): 'blue', (255, 255, 0): 'yellow',
    (0, 255, 255): 'cyan', (255, 0, 255): 'magenta', (255, 255, 255): 'white', (0, 0, 0): 'black',
}


@dataclass(frozen=True)
class ControllerConfig:
    """Every tunable of the controller; field names are the ROS parameter names."""

    boundary_x: float = 5.5
    left_r: int = 255
    left_g: int = 0
    left_b: int = 0
    right_r: int = 0
    right_g: int = 255
    right_b: int = 0
    pen_width: int = 3
    wall_margin_low: float = 2.0
    wall_margin_high: float = 9.0
    cruise_speed: float = 5.0
    wall_speed: float = 1.0
    wall_turn_rate: float = 0.9

    @property
    def left_colour(self) -> Rgb:
        return (self.left_r, self.left_g, self.left_b)

    @property
    def right_colour(self) -> Rgb:
        return (self.right_r, self.right_g, self.right_b)


@dataclass(frozen=True)
class ParameterSpec:
    """Allowed range (inclusive) and meaning of one parameter."""

    low: float
    high: float
    description: str

    def allowed(self, default: float) -> str:
        kind = 'an integer' if isinstance(default, int) else 'a number'
        return f'{kind} in [{self.low:g}, {self.high:g}]'


_CHANNEL = (0, 255)
PARAMETERS: dict[str, ParameterSpec] = {
    'boundary_x': ParameterSpec(0.0, CANVAS_SIZE, 'x (m) where the pen switches colour: '
                                                  'left colour below it, right colour from it on'),
    'left_r': ParameterSpec(*_CHANNEL, 'red channel of the pen left of boundary_x'),
    'left_g': ParameterSpec(*_CHANNEL, 'green channel of the pen left of boundary_x'),
    'left_b': ParameterSpec(*_CHANNEL, 'blue channel of the pen left of boundary_x'),
    'right_r': ParameterSpec(*_CHANNEL, 'red channel of the pen right of boundary_x'),
    'right_g': ParameterSpec(*_CHANNEL, 'green channel of the pen right of boundary_x'),
    'right_b': ParameterSpec(*_CHANNEL, 'blue channel of the pen right of boundary_x'),
    # set_pen width 0 would mean 1 px in turtlesim, so 0 is refused instead of surprising.
    'pen_width': ParameterSpec(1, 255, 'pen width in pixels'),
    'wall_margin_low': ParameterSpec(0.0, CANVAS_SIZE, 'x or y (m) below which the turtle is '
                                                       'near a wall; must be < wall_margin_high'),
    'wall_margin_high': ParameterSpec(0.0, CANVAS_SIZE, 'x or y (m) above which the turtle is '
                                                        'near a wall; must be > wall_margin_low'),
    'cruise_speed': ParameterSpec(0.0, 20.0, 'forward speed (m/s) away from the walls'),
    'wall_speed': ParameterSpec(0.0, 20.0, 'forward speed (m/s) near a wall'),
    'wall_turn_rate': ParameterSpec(-10.0, 10.0, 'turn rate (rad/s) near a wall, '
                                                 'positive = counter-clockwise'),
}
DEFAULTS = ControllerConfig()
assert [f.name for f in fields(ControllerConfig)] == list(PARAMETERS)


def side_of(x: float, boundary_x: float) -> Side:
    """LEFT strictly below the boundary, RIGHT from it on (x == boundary is RIGHT)."""
    return Side.LEFT if x < boundary_x else Side.RIGHT


def near_wall(x: float, y: float, config: ControllerConfig) -> bool:
    low, high = config.wall_margin_low, config.wall_margin_high
    return x < low or x > high or y < low or y > high


def velocity_for(x: float, y: float, config: ControllerConfig) -> tuple[float, float]:
    """(linear.x, angular.z) for a pose: slow down and turn near a wall, else go straight."""
    if near_wall(x, y, config):
        return config.wall_speed, config.wall_turn_rate
    return config.cruise_speed, 0.0


def colour_for(side: Side, config: ControllerConfig) -> Rgb:
    return config.left_colour if side is Side.LEFT else config.right_colour


def colour_name(colour: Rgb) -> str:
    """'red (255, 0, 0)' for a known colour, '(12, 34, 56)' otherwise."""
    name = COLOUR_NAMES.get(colour)
    return f'{name} {colour}' if name else str(colour)


def pen_call_due(requested: Side | None, current: Side | None) -> bool:
    """A set_pen call is due when the turtle's side differs from the side last asked for.

    `requested` is None when nothing was asked yet, or when what was asked no longer holds
    (the server went away, a new turtle appeared, a call failed, the colours changed).
    `current` is None until the first pose.
    """
    return current is not None and requested is not current


def check_parameters(config: ControllerConfig) -> list[str]:
    """Every rule `config` breaks, each as a message naming the parameter and what is allowed."""
    problems = []
    for name, spec in PARAMETERS.items():
        value = getattr(config, name)
        default = getattr(DEFAULTS, name)
        wanted = int if isinstance(default, int) else (int, float)
        if isinstance(value, bool) or not isinstance(value, wanted):
            problems.append(f"parameter '{name}' must be {spec.allowed(default)}, "
                            f'got {value!r} ({type(value).__name__})')
        elif not spec.low <= value <= spec.high:
            problems.append(f"parameter '{name}' = {value} is out of range: "
                            f'must be {spec.allowed(default)}')
    if not problems and config.wall_margin_low >= config.wall_margin_high:
        problems.append(
            f"parameter 'wall_margin_low' = {config.wall_margin_low} must be below "
            f"'wall_margin_high' = {config.wall_margin_high} (both in [0, {CANVAS_SIZE:g}])")
    return problems


def with_changes(config: ControllerConfig, changes: dict[str, object]) -> ControllerConfig:
    """`config` with some parameters replaced; ints given for float parameters become floats."""
    converted = {}
    for name, value in changes.items():
        if isinstance(getattr(DEFAULTS, name), float) and type(value) is int:
            value = float(value)
        converted[name] = value
    return replace(config, **converted)
