import sys

from example_interfaces.srv import AddTwoInts
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node('minimal_client_async')
    cli = node.create_client(AddTwoInts, 'add_two_ints')
    while not cli.wait_for_service(timeout_sec=1.0):
        node.get_logger().info('service not available, waiting again...')
    future = cli.call_async(AddTwoInts.Request(a=int(sys.argv[1]), b=int(sys.argv[2])))

    while rclpy.ok():
        rclpy.spin_once(node)
        if future.done():
            #Get response
            node.get_logger().info('Result of add_two_ints: %d' % future.result().sum)
            break

    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
