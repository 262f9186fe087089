"""The baseline for the round-trip benchmark: the smallest rclpy std_srvs/SetBool server."""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_srvs.srv import SetBool


class BaselineServer(Node):
    def __init__(self) -> None:
        super().__init__('baseline_setbool_server')
        self.create_service(SetBool, 'baseline_set_bool', self.on_set_bool)

    def on_set_bool(self, request: SetBool.Request, response: SetBool.Response) -> SetBool.Response:
        response.success = request.data
        return response


def main() -> None:
    try:
        rclpy.init()
        rclpy.spin(BaselineServer())
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
