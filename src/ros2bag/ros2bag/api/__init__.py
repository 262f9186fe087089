"""What ros2bag's verbs share (upstream's `ros2bag.api`): QoS override files, argument checks."""

from __future__ import annotations

import argparse
import os
from typing import Any, NoReturn

from ros2cli.verb_context import VerbContext

_DURATION_KEYS = ('deadline', 'lifespan', 'liveliness_lease_duration')
_POLICY_KEYS = {'history': 'QoSHistoryPolicy', 'reliability': 'QoSReliabilityPolicy',
                'durability': 'QoSDurabilityPolicy', 'liveliness': 'QoSLivelinessPolicy'}


def exit_now(result: int | str, context: VerbContext) -> NoReturn:
    """End the `ros2 bag` process with `result` as `ros2` would (a string: on the verb's stderr,
    status 1), without Python's and the libraries' teardown (the player's or recorder's context
    is shut down: Fast DDS's static teardown is skipped). Only once everything is closed."""
    code = result if isinstance(result, int) else 1
    try:
        if isinstance(result, str):
            print(result, file=context.stderr)
        context.stdout.flush()
        context.stderr.flush()
    except (BrokenPipeError, ValueError):
        pass  # nobody reads any more (`| head`), or a stream was closed
    os._exit(code)


def print_error(message: str) -> str:
    """The line `ros2 bag` prints for a refused request (returned to the CLI for stderr)."""
    return f'[ERROR] [ros2bag]: {message}'


def dict_to_duration(time_dict: Any) -> Any:
    """An rclpy Duration from rosbag2's `{sec: S, nsec: N}`; ValueError unless both are given."""
    from rclpy.duration import Duration

    if not isinstance(time_dict, dict) or set(time_dict) != {'sec', 'nsec'}:
        raise ValueError('Time overrides must include both seconds (sec) and nanoseconds (nsec).')
    return Duration(seconds=time_dict['sec'], nanoseconds=time_dict['nsec'])


def interpret_dict_as_qos_profile(qos_profile_dict: dict) -> Any:
    """An rclpy QoSProfile from one topic's overrides; ValueError naming a bad key or value."""
    import rclpy.qos

    if not isinstance(qos_profile_dict, dict):
        raise ValueError(f'A QoS profile must be a mapping of policies, got {qos_profile_dict!r}')
    values: dict[str, Any] = {}
    for key, value in qos_profile_dict.items():
        if key in _POLICY_KEYS:
            policy = getattr(rclpy.qos, _POLICY_KEYS[key])
            try:
                values[key] = policy.get_from_short_key(str(value))
            except KeyError:
                raise ValueError(f"Invalid value '{value}' for QoS policy '{key}' (allowed: "
                                 f"{', '.join(policy.short_keys())})") from None
        elif key == 'depth':
            if not isinstance(value, int) or isinstance(value, bool) or value < 0:
                raise ValueError(f"'depth' must be a non-negative integer, got {value!r}")
            values[key] = value
        elif key in _DURATION_KEYS:
            duration = dict_to_duration(value)
            if duration.nanoseconds < 0:
                raise ValueError(f"'{key}' must not be negative, got {value!r}")
            values[key] = duration
        elif key == 'avoid_ros_namespace_conventions':
            values[key] = bool(value)
        else:
            raise ValueError(f'Unexpected key `{key}` for QoS profile.')
    try:
        return rclpy.qos.QoSProfile(**values)
    except rclpy.qos.InvalidQoSProfileException as error:
        raise ValueError(str(error)) from None


def convert_yaml_to_qos_profile(qos_profile_dict: Any) -> dict[str, Any]:
    """{topic: QoSProfile} from a loaded override file."""
    if not isinstance(qos_profile_dict, dict):
        raise ValueError('A QoS override file must map topic names to QoS policies')
    return {str(topic): interpret_dict_as_qos_profile(profile)
            for topic, profile in qos_profile_dict.items()}


def load_qos_overrides(stream: Any) -> dict[str, Any]:
    """The overrides of an opened --qos-profile-overrides-path file; ValueError if invalid."""
    import yaml

    with stream:
        try:
            document = yaml.safe_load(stream)
        except yaml.YAMLError as error:
            mark = getattr(error, 'problem_mark', None)
            where = f' (line {mark.line + 1})' if mark else ''
            raise ValueError(f"'{stream.name}' is not valid YAML{where}") from None
    return convert_yaml_to_qos_profile(document or {})


def add_qos_overrides_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        '--qos-profile-overrides-path', type=argparse.FileType('r'),
        help='Path to a yaml file defining overrides of the QoS profile for specific topics.')


def check_positive_float(value: str) -> float:
    number = float(value)
    if number <= 0.0:
        raise argparse.ArgumentTypeError(f'{value} is not in the valid range (> 0.0)')
    return number


def check_not_negative_float(value: str) -> float:
    number = float(value)
    if number < 0.0:
        raise argparse.ArgumentTypeError(f'{value} is not in the valid range (>= 0.0)')
    return number
