"""`ros2 run nav2_behaviors behavior_server`: Nav2's behaviour server, a lifecycle node.

The `behavior_plugins` (upstream's default: spin, backup, drive_on_heading, wait; Nav2's
params file adds assisted_teleop) each get an action server of their name and publish on
cmd_vel. Those that move check the local costmap another node publishes
(`local_costmap_topic`, `local_footprint_topic`) before each command; the robot's pose is TF
local_frame -> robot_base_frame.
"""

from __future__ import annotations

import sys
from typing import Any

from nav2_util.lifecycle_node import LifecycleNode
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.executors import MultiThreadedExecutor
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.parameter import Parameter
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from tf2_ros import Buffer, TransformListener

from nav2_behaviors.costmap_topic_collision_checker import (
    CostmapSubscriber,
    CostmapTopicCollisionChecker,
    FootprintSubscriber,
)
from nav2_behaviors.plugins.assisted_teleop import AssistedTeleop
from nav2_behaviors.plugins.drive_on_heading import BackUp, DriveOnHeading
from nav2_behaviors.plugins.spin import Spin
from nav2_behaviors.plugins.wait import Wait
from nav2_behaviors.timed_behavior import CostmapInfoType, TimedBehavior

# /tf as upstream's listener takes it, but only the latest few: a listener that falls behind
# (a loaded machine) drops old transforms instead of working through a 100-deep backlog,
# which left the pose a behaviour starts from 0.7 s old (a spin then overshot by 0.36 rad).
TF_QOS = QoSProfile(depth=5, durability=DurabilityPolicy.VOLATILE,
                    history=HistoryPolicy.KEEP_LAST)

# The plugin types this workspace has, by upstream's class name.
BEHAVIOR_TYPES: dict[str, type[TimedBehavior]] = {
    'nav2_behaviors::Spin': Spin,
    'nav2_behaviors::BackUp': BackUp,
    'nav2_behaviors::DriveOnHeading': DriveOnHeading,
    'nav2_behaviors::Wait': Wait,
    'nav2_behaviors::AssistedTeleop': AssistedTeleop,
}
DEFAULT_IDS = ['spin', 'backup', 'drive_on_heading', 'wait']
DEFAULT_TYPES = ['nav2_behaviors::Spin', 'nav2_behaviors::BackUp',
                 'nav2_behaviors::DriveOnHeading', 'nav2_behaviors::Wait']
# what the plugins declare at configure: known names, for the unknown-parameter warning
PLUGIN_PARAMETERS = {'simulate_ahead_time': 2.0, 'max_rotational_vel': 1.0,
                     'min_rotational_vel': 0.4, 'rotational_acc_lim': 3.2,
                     'projection_time': 1.0, 'simulation_time_step': 0.1,
                     'cmd_vel_teleop': 'cmd_vel_teleop', 'action_server_result_timeout': 10.0,
                     'enable_stamped_cmd_vel': False}


def plugin_key(plugin_type: str) -> str:
    """'nav2_behaviors/Spin' (pluginlib's spelling) -> 'nav2_behaviors::Spin'."""
    return plugin_type.replace('/', '::')


class BehaviorServer(LifecycleNode):
    def __init__(self) -> None:
        super().__init__('behavior_server')
        declare_checked(self, 'local_costmap_topic', 'local_costmap/costmap_raw')
        declare_checked(self, 'global_costmap_topic', 'global_costmap/costmap_raw')
        declare_checked(self, 'local_footprint_topic', 'local_costmap/published_footprint')
        declare_checked(self, 'global_footprint_topic', 'global_costmap/published_footprint')
        declare_checked(self, 'cycle_frequency', 10.0)
        self.behavior_ids: list[str] = declare_checked(self, 'behavior_plugins', DEFAULT_IDS)
        if self.behavior_ids == DEFAULT_IDS:
            for name, kind in zip(DEFAULT_IDS, DEFAULT_TYPES, strict=False):
                declare_checked(self, f'{name}.plugin', kind)
        declare_checked(self, 'local_frame', 'odom')
        declare_checked(self, 'global_frame', 'map')
        declare_checked(self, 'robot_base_frame', 'base_link')
        declare_checked(self, 'transform_tolerance', 0.1)
        self.behaviors: list[TimedBehavior] = []
        self.tf_buffer: Buffer | None = None
        self._tf_listener: TransformListener | None = None
        self._topic_handles: list[Any] = []
        self._checked_parameters = False

    # --- lifecycle -----------------------------------------------------------------------
    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring')
        if self.get_parameter('cycle_frequency').value <= 0.0:
            self.get_logger().error(
                f"Parameter 'cycle_frequency' must be > 0 Hz, got "
                f"{self.get_parameter('cycle_frequency').value}")
            return TransitionCallbackReturn.FAILURE
        self.tf_buffer = Buffer()
        # TF on its own thread: a behaviour's cycle must not wait behind costmap messages
        self._tf_listener = TransformListener(self.tf_buffer, self, spin_thread=True,
                                              qos=TF_QOS)
        if not self._load_behavior_plugins():
            self.release()
            return TransitionCallbackReturn.FAILURE
        local, global_ = self._collision_checkers()
        for name, behavior in zip(self.behavior_ids, self.behaviors, strict=False):
            behavior.configure(self, name, self.tf_buffer, local, global_)
        if not self._checked_parameters:
            for name, default in PLUGIN_PARAMETERS.items():
                if not self.has_parameter(name) and name in self._parameter_overrides:
                    declare_checked(self, name, default)  # given, if no plugin reads it
            warn_unknown_parameters(self)
            self._checked_parameters = True
        return TransitionCallbackReturn.SUCCESS

    def _load_behavior_plugins(self) -> bool:
        for name in self.behavior_ids:
            key = f'{name}.plugin'
            kind = self.get_parameter(key).value if self.has_parameter(key) else \
                declare_checked(self, key, Parameter.Type.STRING)
            if not kind:
                self.get_logger().fatal(f"Can not get 'plugin' param value for {name}")
                return False
            self.get_logger().info(f'Creating behavior plugin {name} of type {kind}')
            cls = BEHAVIOR_TYPES.get(plugin_key(kind))
            if cls is None:
                self.get_logger().fatal(
                    f'Failed to create behavior {name} of type {kind}. Exception: According '
                    f"to the loaded plugin descriptions the class {kind} with base class type "
                    f"nav2_core::Behavior does not exist. Declared types are  "
                    f"{'  '.join(sorted(BEHAVIOR_TYPES))}")
                return False
            self.behaviors.append(cls())
        return True

    def _collision_checkers(self) -> tuple[Any, Any]:
        needs = {behavior.resource_info for behavior in self.behaviors}
        need_local = bool(needs & {CostmapInfoType.LOCAL, CostmapInfoType.BOTH})
        need_global = bool(needs & {CostmapInfoType.GLOBAL, CostmapInfoType.BOTH})
        base = self.get_parameter('robot_base_frame').value
        tolerance = self.get_parameter('transform_tolerance').value
        checkers: list[Any] = []
        for scope, needed in (('local', need_local), ('global', need_global)):
            if not needed:
                checkers.append(None)
                continue
            costmap = CostmapSubscriber(self, self.get_parameter(f'{scope}_costmap_topic').value)
            footprint = FootprintSubscriber(
                self, self.get_parameter(f'{scope}_footprint_topic').value, self.tf_buffer,
                base, tolerance)
            checker = CostmapTopicCollisionChecker(costmap, footprint, self.get_name())
            self._topic_handles += checker.handles()
            checkers.append(checker)
        return checkers[0], checkers[1]

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        result = super().on_activate(state)  # the cmd_vel publishers first
        for behavior in self.behaviors:
            behavior.activate()
        return result

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        for behavior in self.behaviors:
            behavior.deactivate()
        return super().on_deactivate(state)

    def release(self) -> None:
        for behavior in self.behaviors:
            if behavior.node is not None:
                behavior.cleanup()
        self.behaviors = []
        for subscription in self._topic_handles:
            self.destroy_subscription(subscription)
        self._topic_handles = []
        self._tf_listener = self.tf_buffer = None


def main(args: list[str] | None = None) -> int:
    with ros_session(args) as stop:
        node = BehaviorServer()
        node.stop_event = stop
        # goals wait for their results on executor threads while the behaviours run on
        # threads of their own: room for a goal, a preempting one and cancels per behaviour
        spin_until_stopped(node, stop, MultiThreadedExecutor(num_threads=6))
    return 0


if __name__ == '__main__':
    sys.exit(main())
