"""`ros2 run demo_nodes_cpp matched_event_detect`: demo_nodes_py's demo under rclcpp's node
name, its count lines ending with a full stop."""
import sys

from demo_nodes_py.events import matched_event_detect


class MatchedEventDetectNode(matched_event_detect.MatchedEventDetectNode):
    NAME = 'matched_event_detect_node'
    END = '.'


def main() -> int:
    return matched_event_detect.main(MatchedEventDetectNode)


if __name__ == '__main__':
    sys.exit(main())
