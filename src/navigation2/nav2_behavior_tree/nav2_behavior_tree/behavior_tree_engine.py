"""BehaviorTreeEngine: Nav2's node set registered by name, trees built from XML, and the
tick loop that runs a tree until it ends, is canceled, or throws."""

from __future__ import annotations

import enum
import time
from collections.abc import Callable
from typing import Any

from nav2_behavior_tree.conditions import CONDITION_NODES
from nav2_behavior_tree.control import CONTROL_NODES
from nav2_behavior_tree.core import Blackboard, NodeStatus, TreeNode
from nav2_behavior_tree.decorators import DECORATOR_NODES
from nav2_behavior_tree.xml_parser import Tree, TreeBuilder


class BtStatus(enum.Enum):
    SUCCEEDED = 'SUCCEEDED'
    FAILED = 'FAILED'
    CANCELED = 'CANCELED'


def builtin_nodes(with_ros: bool = True) -> dict[str, type[TreeNode]]:
    """Every node type by its XML name; `with_ros=False` leaves out the ROS leaves (pure
    tests run without rclpy's interfaces)."""
    from nav2_behavior_tree.helpers import ACTION_HELPERS, HELPER_DECORATORS
    registry: dict[str, type[TreeNode]] = {}
    for group in (CONTROL_NODES, DECORATOR_NODES, CONDITION_NODES, ACTION_HELPERS,
                  HELPER_DECORATORS):
        registry.update(group)
    if with_ros:
        from nav2_behavior_tree.actions import ACTION_NODES
        from nav2_behavior_tree.more_nodes import MORE_NODES
        registry.update(ACTION_NODES)
        registry.update(MORE_NODES)
    return registry


class BehaviorTreeEngine:
    def __init__(self, extra_nodes: dict[str, type[TreeNode]] | None = None,
                 with_ros: bool = True, log: Callable[[str], None] | None = None) -> None:
        self.registry = builtin_nodes(with_ros)
        self.registry.update(extra_nodes or {})
        self.builder = TreeBuilder(self.registry)
        self.log = log or (lambda line: None)

    def create_tree_from_file(self, path: str, blackboard: Blackboard) -> Tree:
        return self.builder.from_file(path, blackboard)

    def create_tree_from_text(self, text: str, blackboard: Blackboard) -> Tree:
        return self.builder.from_text(text, blackboard)

    def run(self, tree: Tree, on_loop: Callable[[], None],
            cancel_requested: Callable[[], bool], loop_duration: float,
            keep_running: Callable[[], bool] = lambda: True) -> BtStatus:
        """Tick every loop_duration seconds until the root ends (upstream's run())."""
        result = NodeStatus.RUNNING
        try:
            while result == NodeStatus.RUNNING and keep_running():
                started = time.monotonic()
                if cancel_requested():
                    tree.halt_tree()
                    return BtStatus.CANCELED
                on_loop()
                result = tree.tick_once()
                rest = loop_duration - (time.monotonic() - started)
                if rest > 0 and result == NodeStatus.RUNNING:
                    time.sleep(rest)
        except Exception as error:  # a node's failure ends the navigation, not the node
            self.log(f'Behavior tree threw exception: {error}. Exiting with failure.')
            return BtStatus.FAILED
        if result == NodeStatus.RUNNING:  # stopped from outside
            tree.halt_tree()
            return BtStatus.CANCELED
        return BtStatus.SUCCEEDED if result == NodeStatus.SUCCESS else BtStatus.FAILED

    @staticmethod
    def halt_all_actions(tree: Tree) -> None:
        tree.halt_tree()


def ros_blackboard(values: dict[str, Any]) -> Blackboard:
    board = Blackboard()
    for key, value in values.items():
        board.set(key, value)
    return board
