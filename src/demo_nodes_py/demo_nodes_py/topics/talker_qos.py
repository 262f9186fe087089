"""`ros2 run demo_nodes_py talker_qos [--reliable] [-n N]`: the talker with a chosen
reliability, stopping after N messages."""
import sys

from node_runtime.spinning import ros_session

from demo_nodes_py.topics import qos_args
from demo_nodes_py.topics.talker import Talker


def main() -> int:
    args, profile = qos_args.parse(sys.argv, 'number of sending attempts')
    with ros_session() as stop:
        node = Talker('talker_qos', profile)
        node.get_logger().info(f'{qos_args.describe(profile)} talker')
        qos_args.spin_cycles(node, args.number_of_cycles, lambda: node.count, stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
