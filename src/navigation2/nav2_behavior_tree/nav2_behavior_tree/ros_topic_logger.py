"""RosTopicLogger: a tree's status changes on `behavior_tree_log` (nav2_msgs/BehaviorTreeLog),
gathered while ticking and published at each flush, as upstream's."""

from __future__ import annotations

import time
from typing import Any

from builtin_interfaces.msg import Time
from nav2_msgs.msg import BehaviorTreeLog, BehaviorTreeStatusChange

from nav2_behavior_tree.core import NodeStatus, TreeNode
from nav2_behavior_tree.xml_parser import Tree


def stamp(seconds: float) -> Time:
    whole = int(seconds)
    return Time(sec=whole, nanosec=int((seconds - whole) * 1e9))


class RosTopicLogger:
    def __init__(self, node: Any, tree: Tree) -> None:
        self.node = node
        self.events: list[BehaviorTreeStatusChange] = []
        self.publisher = node.create_publisher(BehaviorTreeLog, 'behavior_tree_log', 10)
        self.uids = {id(tree_node): uid for uid, tree_node in enumerate(tree.nodes, start=1)}
        self.tree = tree
        for tree_node in tree.nodes:
            tree_node.observer = self.on_status_change

    def on_status_change(self, tree_node: TreeNode, previous: NodeStatus,
                         current: NodeStatus) -> None:
        self.events.append(BehaviorTreeStatusChange(
            timestamp=stamp(time.time()), node_name=tree_node.name,
            uid=self.uids.get(id(tree_node), 0), previous_status=previous.value,
            current_status=current.value))

    def flush(self) -> None:
        if self.events:
            events, self.events = self.events, []
            self.publisher.publish(BehaviorTreeLog(
                timestamp=self.node.get_clock().now().to_msg(), event_log=events))

    def close(self) -> None:
        for tree_node in self.tree.nodes:
            tree_node.observer = None
        self.node.destroy_publisher(self.publisher)
