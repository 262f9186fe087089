"""`ros2 run nav2_map_server map_saver_cli -f <mapname> ...`: save one map from a topic.

Upstream's arguments, help text and log lines; it runs the map_saver node for one map and
exits 0 when it is saved, 1 when not, 255 for a bad command line. Unlike upstream, a value
that is not a number for --occ/--free, an unknown --mode and a --fmt other than pgm, png or
bmp are refused in one line before anything is done (upstream reads them as 0, trinary, or
lets the image library decide).
"""

from __future__ import annotations

import sys

from node_runtime.spinning import ros_session
from rclpy.logging import get_logger

from nav2_map_server.map_io import SaveParameters, map_mode_from_string, validate_save_parameters
from nav2_map_server.map_saver import MapSaver

USAGE_STRING = (
    'Usage:\n'
    '  map_saver_cli [arguments] [--ros-args ROS remapping args]\n'
    '\n'
    'Arguments:\n'
    '  -h/--help\n'
    '  -t <map_topic>\n'
    '  -f <mapname>\n'
    '  --occ <threshold_occupied>\n'
    '  --free <threshold_free>\n'
    '  --fmt <image_format>\n'
    '  --mode trinary(default)/scale/raw\n'
    '\n'
    'NOTE: --ros-args should be passed at the end of command line')

OPTIONS = ('-t', '-f', '--occ', '--free', '--mode', '--fmt')
EXIT_INVALID = 255  # upstream's main returns -1


class ArgumentError(ValueError):
    pass


def _threshold(option: str, text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ArgumentError(f'Wrong argument: {option} should be followed by a number from '
                            f"0 to 1, got '{text}'") from None
    if not 0.0 <= value <= 1.0:
        raise ArgumentError(f'Wrong argument: {option} should be followed by a number from '
                            f"0 to 1, got '{text}'")
    return value


def parse_arguments(arguments: list[str]) -> tuple[str, SaveParameters] | None:
    """(map topic, save parameters), or None for -h; raises ArgumentError (one line)."""
    map_topic, save = 'map', SaveParameters()
    position = 0
    while position < len(arguments):
        argument = arguments[position]
        if argument in ('-h', '--help'):
            return None
        if argument == '--ros-args':
            break
        if argument not in OPTIONS:
            raise ArgumentError(f'Wrong argument: {argument}')
        if position + 1 == len(arguments):
            raise ArgumentError(f'Wrong argument: {argument} should be followed by a value.')
        value = arguments[position + 1]
        position += 2
        if argument == '-t':
            map_topic = value
        elif argument == '-f':
            save.map_file_name = value
        elif argument == '--occ':
            save.occupied_thresh = _threshold(argument, value)
        elif argument == '--free':
            save.free_thresh = _threshold(argument, value)
        elif argument == '--fmt':
            save.image_format = value
        else:
            try:
                save.mode = map_mode_from_string(value)
            except ValueError:
                raise ArgumentError(f"Wrong argument: --mode should be followed by trinary, "
                                    f"scale or raw, got '{value}'") from None
    try:
        validate_save_parameters(save)
    except ValueError as error:
        raise ArgumentError(f'Wrong argument: {error}') from None
    return map_topic, save


def main() -> int:
    with ros_session() as stop:
        logger = get_logger('map_saver_cli')
        try:
            parsed = parse_arguments(sys.argv[1:])
        except ArgumentError as error:
            logger.error(str(error))
            return EXIT_INVALID
        if parsed is None:
            print(USAGE_STRING, flush=True)
            return 0
        map_topic, save = parsed
        node = MapSaver()
        node.stop_event = stop
        node.on_configure()  # as upstream: the state machine is not involved
        try:
            saved = node.save_map_topic_to_file(map_topic, save)
        finally:
            node.destroy_node()
    return 0 if saved else 1


if __name__ == '__main__':
    sys.exit(main())
