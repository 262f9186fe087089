"""The `logger_config` node: `/config_logger` (logging_demo/srv/ConfigLogger) sets the level
of any logger of this process by name; the empty name is the default level of every logger
not set explicitly."""
from rclpy.logging import get_logging_severity_from_string, set_logger_level
from rclpy.node import Node

from logging_demo.srv import ConfigLogger


class LoggerConfig(Node):
    def __init__(self) -> None:
        super().__init__('logger_config')
        self.srv = self.create_service(ConfigLogger, 'config_logger', self.on_request)

    def on_request(self, request: ConfigLogger.Request,
                   response: ConfigLogger.Response) -> ConfigLogger.Response:
        self.get_logger().info(f"Incoming request: logger '{request.logger_name}', "
                               f"severity '{request.level}'")
        try:
            severity = get_logging_severity_from_string(request.level)
        except (RuntimeError, ValueError):
            self.get_logger().error(f"Unknown severity '{request.level}'")
            response.success = False
            return response
        try:
            set_logger_level(request.logger_name, severity)
        except (RuntimeError, ValueError) as error:
            self.get_logger().error(f'Error setting severity: {error}')
            response.success = False
            return response
        response.success = True
        return response
