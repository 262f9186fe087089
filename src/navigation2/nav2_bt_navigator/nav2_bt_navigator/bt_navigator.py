"""`ros2 run nav2_bt_navigator bt_navigator`: Nav2's BT navigator, a lifecycle node.

It serves `navigate_to_pose` and `navigate_through_poses` (the `navigators` and their
`plugin:` types) by running behavior trees whose leaves call the other servers. As upstream,
the trees' clients live on a node of their own per navigator
(`bt_navigator_<action>_rclcpp_node`), all spun by this process's multi-threaded executor.
"""

from __future__ import annotations

import math
import sys
import threading
import time

from nav2_util.lifecycle_node import LifecycleNode
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from nav_msgs.msg import Odometry
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.executors import MultiThreadedExecutor
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.node import Node
from rclpy.parameter import Parameter
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener

from nav2_bt_navigator.navigators import (
    NAVIGATOR_TYPES,
    FeedbackUtils,
    Muxer,
    Navigator,
    client_node_name,
)

DEFAULT_NAVIGATORS = ['navigate_to_pose', 'navigate_through_poses']
DEFAULT_TYPES = ['nav2_bt_navigator::NavigateToPoseNavigator',
                 'nav2_bt_navigator::NavigateThroughPosesNavigator']
DEFAULT_ERROR_CODE_NAMES = ['follow_path_error_code', 'compute_path_error_code']


class OdomSmoother:
    """nav2_util::OdomSmoother: the mean twist of the odometry of the last 0.3 s."""

    def __init__(self, node: Node, topic: str, window: float = 0.3) -> None:
        self.window = window
        self.samples: list[tuple[float, float, float]] = []
        self.lock = threading.Lock()
        self.subscription = node.create_subscription(Odometry, topic, self.on_odom, 10)

    def on_odom(self, msg: Odometry) -> None:
        now = time.monotonic()
        with self.lock:
            self.samples.append((now, msg.twist.twist.linear.x, msg.twist.twist.linear.y))
            self.samples = [s for s in self.samples if now - s[0] <= self.window]

    def speed(self) -> float:
        with self.lock:
            if not self.samples:
                return 0.0
            vx = sum(s[1] for s in self.samples) / len(self.samples)
            vy = sum(s[2] for s in self.samples) / len(self.samples)
        return math.hypot(vx, vy)


class BtNavigator(LifecycleNode):
    def __init__(self) -> None:
        super().__init__('bt_navigator')
        self.get_logger().info('Creating')
        p = {name: declare_checked(self, name, default) for name, default in (
            ('plugin_lib_names', Parameter.Type.STRING_ARRAY), ('transform_tolerance', 0.1),
            ('global_frame', 'map'), ('robot_base_frame', 'base_link'), ('odom_topic', 'odom'),
            ('navigators', DEFAULT_NAVIGATORS), ('bt_loop_duration', 10),
            ('default_server_timeout', 20), ('default_cancel_timeout', 20),
            ('action_server_result_timeout', 900.0), ('always_reload_bt_xml', False),
            ('wait_for_service_timeout', 1000),
            ('error_code_names', Parameter.Type.STRING_ARRAY),
            ('goal_blackboard_id', 'goal'), ('goals_blackboard_id', 'goals'),
            ('path_blackboard_id', 'path'), ('default_nav_to_pose_bt_xml', ''),
            ('default_nav_through_poses_bt_xml', ''), ('goal_reached_tol', 0.25))}
        self.navigator_types = {}
        for index, name in enumerate(p['navigators'] or []):
            default = DEFAULT_TYPES[index] if p['navigators'] == DEFAULT_NAVIGATORS else ''
            self.navigator_types[name] = declare_checked(self, f'{name}.plugin', default)
            for key, value in (('enable_groot_monitoring', False), ('groot_server_port', 1667)):
                declare_checked(self, f'{name}.{key}', value)
        if p['error_code_names'] is None:
            self.get_logger().warning(
                'Error_code parameters were not set. Using default values of: '
                f"{' '.join(DEFAULT_ERROR_CODE_NAMES)}\nMake sure these match your BT and there "
                'are not other sources of error codes you reported to your application')
            p['error_code_names'] = DEFAULT_ERROR_CODE_NAMES
        else:
            self.get_logger().info(
                f"Error_code parameters were set to: {' '.join(p['error_code_names'])}")
        warn_unknown_parameters(self)
        self.params = p
        self.tf_buffer: Buffer | None = None
        self._tf_listener: TransformListener | None = None
        self.odom: OdomSmoother | None = None
        self.navigators: list[Navigator] = []
        self.client_nodes: list[Node] = []

    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring')
        p = self.params
        self.tf_buffer = Buffer()
        self._tf_listener = TransformListener(self.tf_buffer, self, spin_thread=False)
        self.odom = OdomSmoother(self, p['odom_topic'])
        utils = FeedbackUtils(self.tf_buffer, p['global_frame'], p['robot_base_frame'],
                              p['transform_tolerance'])
        settings = dict(p, bt_loop_duration=p['bt_loop_duration'] / 1000.0)
        muxer = Muxer()
        for name, kind in self.navigator_types.items():
            cls = NAVIGATOR_TYPES.get(kind.replace('/', '::'))
            self.get_logger().info(f'Creating navigator id {name} of type {kind}')
            if cls is None:
                self.get_logger().fatal(
                    f'Failed to create navigator id {name}. Exception: According to the loaded '
                    f"plugin descriptions the class {kind} with base class type "
                    'nav2_core::NavigatorBase does not exist. Declared types are  '
                    f"{'  '.join(NAVIGATOR_TYPES)}")
                self.release()
                return TransitionCallbackReturn.FAILURE
            client = Node(client_node_name(self, name), parameter_overrides=[
                Parameter('use_sim_time', value=self.get_parameter('use_sim_time').value)])
            self.client_nodes.append(client)
            if self.executor is not None:
                self.executor.add_node(client)
            blackboard = {
                'node': client, 'tf_buffer': self.tf_buffer, 'odom_smoother': self.odom,
                'global_frame': p['global_frame'], 'robot_base_frame': p['robot_base_frame'],
                'transform_tolerance': p['transform_tolerance'],
                'server_timeout': p['default_server_timeout'] / 1000.0,
                'cancel_timeout': p['default_cancel_timeout'] / 1000.0,
                'bt_loop_duration': p['bt_loop_duration'] / 1000.0,
                'wait_for_service_timeout': p['wait_for_service_timeout'] / 1000.0,
                'goal_reached_tol': p['goal_reached_tol'], 'number_recoveries': 0}
            self.navigators.append(cls(self, name, settings, blackboard, utils, self.odom,
                                       muxer))
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        for navigator in self.navigators:
            if not navigator.server.activate():
                for started in self.navigators:
                    started.server.deactivate()
                return TransitionCallbackReturn.FAILURE
        return super().on_activate(state)

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        for navigator in self.navigators:
            navigator.server.deactivate()
        return super().on_deactivate(state)

    def release(self) -> None:
        for navigator in self.navigators:
            navigator.server.cleanup()
            navigator.close()
        for client in self.client_nodes:
            if self.executor is not None:
                self.executor.remove_node(client)
            client.destroy_node()
        if self.odom is not None:
            self.destroy_subscription(self.odom.subscription)
        if self._tf_listener is not None:
            self._tf_listener.unregister()
        self.navigators, self.client_nodes, self.odom = [], [], None
        self._tf_listener = self.tf_buffer = None

    def on_cleanup(self, state: State) -> TransitionCallbackReturn:
        result = super().on_cleanup(state)
        self.get_logger().info('Completed Cleaning up')
        return result


def main(args: list[str] | None = None) -> int:
    with ros_session(args) as stop:
        node = BtNavigator()
        node.stop_event = stop
        # goals wait for their outcome, trees tick on their own threads, clients' futures
        # complete here: several threads, so none of them waits for another
        spin_until_stopped(node, stop, MultiThreadedExecutor(num_threads=8))
    return 0


if __name__ == '__main__':
    sys.exit(main())
