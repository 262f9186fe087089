"""`ros2 run demo_nodes_py listener_qos [--reliable] [-n N]`: the listener with a chosen
reliability, stopping after N messages heard."""
import sys

from node_runtime.spinning import ros_session

from demo_nodes_py.topics import qos_args
from demo_nodes_py.topics.listener import Listener


def main() -> int:
    args, profile = qos_args.parse(sys.argv, 'max number of spin_once iterations')
    with ros_session() as stop:
        node = Listener('listener_qos', profile)
        node.get_logger().info(f'{qos_args.describe(profile)} listener')
        qos_args.spin_cycles(node, args.number_of_cycles, lambda: node.heard, stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
