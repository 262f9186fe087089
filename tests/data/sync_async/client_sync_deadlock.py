import sys
from threading import Thread

from example_interfaces.srv import AddTwoInts
import rclpy
from std_msgs.msg import String
from rclpy.node import Node


class MinimalClientSync(Node):

    def __init__(self):
        super().__init__('minimal_client_sync')
        self.cli = self.create_client(AddTwoInts, 'add_two_ints')
        while not self.cli.wait_for_service(timeout_sec=1.0):
            self.get_logger().info('service not available, waiting again...')
        self.req = AddTwoInts.Request()

    def send_request(self):
        self.req.a = int(sys.argv[1])
        self.req.b = int(sys.argv[2])
        return self.cli.call(self.req)
        # This only works because rclpy.spin() is called in a separate thread below.
        # Another configuration, like spinning later in main() or calling this method from a timer callback, would result in a deadlock.


def main():
    rclpy.init()

    minimal_client = MinimalClientSync()

    def trigger_request(msg):
        response = minimal_client.send_request()  # This will cause deadlock
        minimal_client.get_logger().info(
            'Result of add_two_ints: for %d + %d = %d' %
            (minimal_client.req.a, minimal_client.req.b, response.sum))
    subscription = minimal_client.create_subscription(String, 'trigger', trigger_request, 10)

    rclpy.spin(minimal_client)


if __name__ == '__main__':
    main()
