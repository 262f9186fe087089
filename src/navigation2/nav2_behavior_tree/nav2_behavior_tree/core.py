"""BehaviorTree.CPP v4's core in Python: node status, blackboard, ports and the node kinds.

A node reads its ports through `get_input` (a literal from the XML converted to the port's
type, or a `{key}` / `{@key}` reference to the blackboard) and writes through `set_output`.
Ticks never block: a node that waits for something returns RUNNING and looks again at the
next tick, as BT.CPP's asynchronous nodes do.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable
from typing import Any, ClassVar


class NodeStatus(enum.Enum):
    IDLE = 'IDLE'
    RUNNING = 'RUNNING'
    SUCCESS = 'SUCCESS'
    FAILURE = 'FAILURE'
    SKIPPED = 'SKIPPED'


def is_active(status: NodeStatus) -> bool:
    """BT::isStatusActive: ticked and not yet reset."""
    return status not in (NodeStatus.IDLE, NodeStatus.SKIPPED)


class BehaviorTreeException(RuntimeError):
    """What BT.CPP throws while building or ticking a tree (the message says where)."""


class Blackboard:
    """Key/value store of one tree; a SubTree's blackboard maps some keys to its parent's."""

    def __init__(self, parent: Blackboard | None = None,
                 remapping: dict[str, str] | None = None, autoremap: bool = False) -> None:
        self._values: dict[str, Any] = {}
        self.parent = parent
        self.remapping = dict(remapping or {})  # child key -> parent key
        self.autoremap = autoremap

    def root(self) -> Blackboard:
        board = self
        while board.parent is not None:
            board = board.parent
        return board

    def _owner(self, key: str) -> tuple[Blackboard, str]:
        if key.startswith('@'):
            return self.root(), key[1:]
        if key in self.remapping and self.parent is not None:
            return self.parent._owner(self.remapping[key])
        if self.autoremap and self.parent is not None and key not in self._values:
            return self.parent._owner(key)
        return self, key

    def get(self, key: str, default: Any = None) -> Any:
        board, name = self._owner(key)
        return board._values.get(name, default)

    def has(self, key: str) -> bool:
        board, name = self._owner(key)
        return name in board._values

    def set(self, key: str, value: Any) -> None:
        board, name = self._owner(key)
        board._values[name] = value

    def keys(self) -> list[str]:
        return list(self._values)


class Port:
    """A port of a node type: direction, value type (for literals) and default."""

    def __init__(self, direction: str, kind: Callable[[str], Any] | None = str,
                 default: Any = None, description: str = '') -> None:
        self.direction = direction  # 'input', 'output' or 'inout'
        self.kind = kind
        self.default = default
        self.description = description


def InputPort(kind: Callable[[str], Any] | None = str, default: Any = None,
              description: str = '') -> Port:
    return Port('input', kind, default, description)


def OutputPort(description: str = '') -> Port:
    return Port('output', None, None, description)


def BidirectionalPort(kind: Callable[[str], Any] | None = None, description: str = '') -> Port:
    return Port('inout', kind, None, description)


def to_bool(text: str) -> bool:
    lowered = text.strip().lower()
    if lowered in ('true', '1'):
        return True
    if lowered in ('false', '0'):
        return False
    raise ValueError(f"'{text}' is not a bool (true/false)")


def to_float(text: str) -> float:
    value = float(text)
    if math.isnan(value):
        raise ValueError(f"'{text}' is not a number")
    return value


def reference(text: str) -> str | None:
    """'{key}' -> 'key'; a literal -> None."""
    stripped = text.strip()
    if len(stripped) >= 2 and stripped[0] == '{' and stripped[-1] == '}':
        return stripped[1:-1]
    return None


def ports(**declared: Port) -> dict[str, Port]:
    """A node type's ports by name (its PORTS)."""
    return dict(declared)


class TreeNode:
    """Base of every node: name, ports, blackboard and the tick/halt protocol."""

    PORTS: ClassVar[dict[str, Port]] = {}

    def __init__(self, name: str, attributes: dict[str, str], blackboard: Blackboard) -> None:
        self.name = name
        self.attributes = attributes  # port name -> literal or {reference}
        self.blackboard = blackboard
        # called with (node, previous, current) on every status change (RosTopicLogger)
        self.observer: Callable[[TreeNode, NodeStatus, NodeStatus], None] | None = None
        self._status = NodeStatus.IDLE
        # set before __init__ by the XML reader (errors name the line)
        self.registration_name = getattr(self, 'registration_name', type(self).__name__)
        self.line = getattr(self, 'line', 0)

    @classmethod
    def ports(cls) -> dict[str, Port]:
        return cls.PORTS

    @property
    def status(self) -> NodeStatus:
        return self._status

    @status.setter
    def status(self, status: NodeStatus) -> None:
        previous, self._status = self._status, status
        if previous != status and self.observer is not None:
            self.observer(self, previous, status)

    # --- ports --------------------------------------------------------------------------
    def get_input(self, port: str, default: Any = None) -> Any:
        """The port's value, or `default` (then the port's own default) when unset."""
        spec = self.ports().get(port)
        text = self.attributes.get(port)
        if text is None:
            if default is not None:
                return default
            return spec.default if spec is not None else None
        key = reference(text)
        if key is not None:
            value = self.blackboard.get(key)
            if value is None:
                return default if default is not None else (
                    spec.default if spec is not None else None)
            if isinstance(value, str) and spec is not None and spec.kind not in (None, str):
                return spec.kind(value)  # a string put there by a SubTree's literal
            return value
        if spec is not None and spec.kind is not None:
            return spec.kind(text)
        return text

    def has_input(self, port: str) -> bool:
        text = self.attributes.get(port)
        if text is None:
            return False
        key = reference(text)
        return key is None or self.blackboard.has(key)

    def get_input_or_blackboard(self, port: str, default: Any = None) -> Any:
        """BT::getInputOrBlackboard: the port if given, else the blackboard entry `port`."""
        if port in self.attributes:
            return self.get_input(port, default)
        value = self.blackboard.get(port)
        return default if value is None else value

    def set_output(self, port: str, value: Any) -> bool:
        text = self.attributes.get(port)
        if text is None:
            return False
        key = reference(text)
        if key is None:
            key = text.strip()  # BT.CPP: an output port given as a plain key name
        self.blackboard.set(key, value)
        return True

    # --- ticks --------------------------------------------------------------------------
    def execute_tick(self) -> NodeStatus:
        status = self.tick()
        self.status = status
        return status

    def tick(self) -> NodeStatus:
        raise NotImplementedError

    def halt(self) -> None:
        self.reset_status()

    def reset_status(self) -> None:
        self.status = NodeStatus.IDLE

    def halt_node(self) -> None:
        """Halt if running (BT.CPP halts only active nodes' children)."""
        if self.status == NodeStatus.RUNNING:
            self.halt()
        self.reset_status()

    def children_list(self) -> list[TreeNode]:
        return []


class ControlNode(TreeNode):
    def __init__(self, name: str, attributes: dict[str, str], blackboard: Blackboard) -> None:
        super().__init__(name, attributes, blackboard)
        self.children: list[TreeNode] = []

    def children_list(self) -> list[TreeNode]:
        return self.children

    def halt_child(self, index: int) -> None:
        self.children[index].halt_node()

    def halt_children(self, start: int = 0) -> None:
        for child in self.children[start:]:
            child.halt_node()

    def halt(self) -> None:
        self.halt_children()
        self.reset_status()


class DecoratorNode(TreeNode):
    def __init__(self, name: str, attributes: dict[str, str], blackboard: Blackboard) -> None:
        super().__init__(name, attributes, blackboard)
        self.child: TreeNode | None = None

    def children_list(self) -> list[TreeNode]:
        return [self.child] if self.child is not None else []

    def halt(self) -> None:
        if self.child is not None:
            self.child.halt_node()
        self.reset_status()


class ConditionNode(TreeNode):
    """A leaf that answers at once (SUCCESS/FAILURE)."""


class ActionNode(TreeNode):
    """A leaf that may run over several ticks."""


class SubTreeNode(DecoratorNode):
    """<SubTree ID=...>: ticks the subtree's root with the subtree's own blackboard."""

    def tick(self) -> NodeStatus:
        return self.child.execute_tick()


def walk(node: TreeNode) -> list[TreeNode]:
    """Every node of a tree, depth first."""
    nodes = [node]
    for child in node.children_list():
        nodes.extend(walk(child))
    return nodes
