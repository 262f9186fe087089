"""The `logger_usage_demo` node: every 0.5 s it publishes a count on logging_demo_count and
logs with several kinds of log call; after 5.5 s it lowers its own level to DEBUG, so that
the debug calls (and what they evaluate) start to run."""
from rclpy.impl.logging_severity import LoggingSeverity
from rclpy.logging import set_logger_level
from rclpy.node import Node
from std_msgs.msg import String

RESET_AFTER = 15


class LoggerUsage(Node):
    def __init__(self) -> None:
        super().__init__('logger_usage_demo')
        self.count = 0
        self.pub = self.create_publisher(String, 'logging_demo_count', 10)
        self.timer = self.create_timer(0.5, self.on_timer)
        self.one_shot_timer = self.create_timer(5.5, self.on_one_shot_timer)

    def on_one_shot_timer(self) -> None:
        self.one_shot_timer.cancel()
        self.get_logger().info('Setting severity threshold to DEBUG')
        set_logger_level(self.get_logger().name, LoggingSeverity.DEBUG)

    def on_timer(self) -> None:
        log = self.get_logger()
        log.info('Timer callback called (this will only log once)', once=True)
        msg = String(data=f'Current count: {self.count}')
        log.info(f"Publishing: '{msg.data}'")
        self.pub.publish(msg)
        # rclcpp's DEBUG_FUNCTION and DEBUG_EXPRESSION evaluate their condition only when
        # debug messages are enabled: the function's own error shows only then.
        if log.is_enabled_for(LoggingSeverity.DEBUG):
            if self.is_divisor_of_twelve(self.count):
                log.debug('Count divides into 12 (function evaluated to true)')
            if self.count % 2 == 0:
                log.debug('Count is even (expression evaluated to true)')
        self.count += 1
        if self.count > RESET_AFTER:
            log.warning('Reseting count to 0')
            self.count = 0

    def is_divisor_of_twelve(self, value: int) -> bool:
        if value == 0:
            self.get_logger().error('Modulo divisor cannot be 0')
            return False
        return 12 % value == 0
