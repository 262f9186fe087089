"""More of Nav2's leaves: the Cancel* nodes, ReinitializeGlobalLocalization, GetPoseFromPath,
ArePosesNear, IsBatteryCharging and WouldASmootherRecoveryHelp."""

from __future__ import annotations

from typing import Any

from action_msgs.srv import CancelGoal
from std_srvs.srv import Empty

from nav2_behavior_tree import robot
from nav2_behavior_tree.bt_action_node import BtServiceNode, service_ports
from nav2_behavior_tree.conditions import AreErrorCodesPresent, IsBatteryLow
from nav2_behavior_tree.core import (
    ActionNode,
    ConditionNode,
    InputPort,
    NodeStatus,
    OutputPort,
    ports,
    to_float,
)

S, F = NodeStatus.SUCCESS, NodeStatus.FAILURE
SMOOTHER_RECOVERABLE = (500, 502, 503, 504)  # UNKNOWN, TIMEOUT, IN_COLLISION, FAILED


class _CancelNode(BtServiceNode):
    """Cancels every goal of an action server: its `_action/cancel_goal` service with a
    zero goal id and stamp (the action protocol's "cancel all")."""

    SERVICE = CancelGoal
    NAME_PORT = 'server_name'
    PORTS = ports(server_name=InputPort(str, None, 'Action server name'),
                  server_timeout=InputPort(int, None, 'Server timeout (ms)'))

    def resolve_server_name(self) -> str:
        return f'{super().resolve_server_name()}/_action/cancel_goal'


def cancel_node(xml_name: str, action_name: str) -> type[_CancelNode]:
    return type(xml_name, (_CancelNode,), {'DEFAULT_NAME': action_name})


CANCEL_NODES = {name: cancel_node(name, action) for name, action in (
    ('CancelControl', 'follow_path'), ('CancelSpin', 'spin'), ('CancelBackUp', 'backup'),
    ('CancelWait', 'wait'), ('CancelDriveOnHeading', 'drive_on_heading'),
    ('CancelAssistedTeleop', 'assisted_teleop'))}


class ReinitializeGlobalLocalization(BtServiceNode):
    """amcl's `reinitialize_global_localization` (std_srvs/Empty)."""

    SERVICE = Empty
    DEFAULT_NAME = 'reinitialize_global_localization'
    PORTS = service_ports()


class GetPoseFromPath(ActionNode):
    PORTS = ports(path=InputPort(None, None, 'Path to extract pose from'),
                  pose=OutputPort('Stamped Extracted Pose'),
                  index=InputPort(int, 0, 'Index of pose to extract from. -1 is end of list'))

    def tick(self) -> NodeStatus:
        path = self.get_input('path')
        index = self.get_input('index')
        if path is None or not path.poses or not -len(path.poses) <= index < len(path.poses):
            return F
        pose = path.poses[index]
        if not pose.header.frame_id:  # a path's poses may leave their header to the path
            pose.header = path.header
        self.set_output('pose', pose)
        return S


class ArePosesNear(ConditionNode):
    PORTS = ports(ref_pose=InputPort(None, None, 'Destination'),
                  target_pose=InputPort(None, None, 'Destination'),
                  global_frame=InputPort(str, None, 'Global frame'),
                  tolerance=InputPort(to_float, 0.5, 'Tolerance'))

    def tick(self) -> NodeStatus:
        ref, target = self.get_input('ref_pose'), self.get_input('target_pose')
        frame = self.get_input('global_frame') or self.blackboard.get('global_frame', 'map')
        if ref is None or target is None:
            return F
        a = robot.transform_pose(self.blackboard, ref, frame)
        b = robot.transform_pose(self.blackboard, target, frame)
        if a is None or b is None:
            return F
        return S if robot.distance(a, b) <= self.get_input('tolerance') else F


class IsBatteryCharging(IsBatteryLow):
    """SUCCESS while BatteryState says POWER_SUPPLY_STATUS_CHARGING (1)."""

    PORTS = ports(battery_topic=InputPort(str, '/battery_status', 'Battery topic'))

    def on_battery_state(self, msg: Any) -> None:
        self.is_low = msg.power_supply_status == msg.POWER_SUPPLY_STATUS_CHARGING


class WouldASmootherRecoveryHelp(AreErrorCodesPresent):
    PORTS = ports(error_code=InputPort(int, 0, 'The active error codes'))
    CODES = SMOOTHER_RECOVERABLE


MORE_NODES = {**CANCEL_NODES, **{cls.__name__: cls for cls in (
    ReinitializeGlobalLocalization, GetPoseFromPath, ArePosesNear, IsBatteryCharging,
    WouldASmootherRecoveryHelp)}}
