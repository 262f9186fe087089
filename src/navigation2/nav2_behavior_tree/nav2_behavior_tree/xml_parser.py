"""BehaviorTree.CPP v4's XML format: <root BTCPP_format="4" main_tree_to_execute=...>,
<BehaviorTree ID=...>, SubTree with port remapping, <include path=...>, the explicit
<Action ID=...> spelling, and <TreeNodesModel> (read past). Every error names its line, as
BT.CPP's "Error at line N: -> ..." does."""

from __future__ import annotations

import os
import xml.parsers.expat
from collections.abc import Callable
from dataclasses import dataclass, field

from nav2_behavior_tree.core import (
    BehaviorTreeException,
    Blackboard,
    ControlNode,
    DecoratorNode,
    NodeStatus,
    SubTreeNode,
    TreeNode,
    reference,
    walk,
)

# Attributes every node takes besides its ports (BT.CPP's reserved names and scripting).
RESERVED = {'name', 'ID', '_autoremap', '_skipIf', '_successIf', '_failureIf', '_while',
            '_onSuccess', '_onFailure', '_onHalted', '_post', '_description', '_uid',
            '_fullpath'}
EXPLICIT_TAGS = {'Action', 'Condition', 'Control', 'Decorator'}
# What Nav2's BtActionServer puts on every subtree's blackboard too: the leaves' ROS handles
# and timeouts (a subtree's blackboard is otherwise empty but for its remapped ports).
SHARED_KEYS = ('node', 'tf_buffer', 'odom_smoother', 'server_timeout', 'cancel_timeout',
               'bt_loop_duration', 'wait_for_service_timeout', 'global_frame',
               'robot_base_frame', 'transform_tolerance', 'goal_reached_tol')


@dataclass
class Element:
    tag: str
    attrib: dict[str, str]
    line: int
    children: list[Element] = field(default_factory=list)


def parse_xml(text: str) -> Element:
    """The document's root element, each element with its line number."""
    parser = xml.parsers.expat.ParserCreate()
    stack: list[Element] = []
    roots: list[Element] = []

    def start(tag: str, attrib: dict[str, str]) -> None:
        element = Element(tag, dict(attrib), parser.CurrentLineNumber)
        (stack[-1].children if stack else roots).append(element)
        stack.append(element)

    parser.StartElementHandler = start
    parser.EndElementHandler = lambda _tag: stack.pop()
    try:
        parser.Parse(text, True)
    except xml.parsers.expat.ExpatError as error:
        raise BehaviorTreeException(f'Error parsing the XML: {error}') from None
    return roots[0]


def header(line: int) -> str:
    return f'Error at line {line}: -> '


class Tree:
    """A built tree: its root, every node, and the root blackboard."""

    def __init__(self, root: TreeNode, blackboard: Blackboard, source: str) -> None:
        self.root = root
        self.blackboard = blackboard
        self.source = source
        self.nodes = walk(root)

    def tick_once(self) -> NodeStatus:
        return self.root.execute_tick()

    def halt_tree(self) -> None:
        self.root.halt_node()

    def close(self) -> None:
        """Destroy the ROS clients and subscriptions the nodes made."""
        for node in self.nodes:
            close = getattr(node, 'close', None)
            if close is not None:
                close()


class TreeBuilder:
    """Builds Trees from XML with the node types of `registry` (ID -> class)."""

    def __init__(self, registry: dict[str, type[TreeNode]]) -> None:
        self.registry = registry

    def from_file(self, path: str, blackboard: Blackboard) -> Tree:
        with open(path, encoding='utf-8') as stream:
            text = stream.read()
        return self.from_text(text, blackboard, path)

    def from_text(self, text: str, blackboard: Blackboard, source: str = '<text>',
                  warn: Callable[[str], None] | None = None) -> Tree:
        root = parse_xml(text)
        if root.tag != 'root':
            raise BehaviorTreeException(f'{header(root.line)}The XML must have a root node '
                                        'called <root>')
        version = root.attrib.get('BTCPP_format')
        if version is None and warn is not None:
            warn('Warnings: The first tag of the XML (<root>) should contain the attribute '
                 '[BTCPP_format="4"]')
        elif version is not None and version != '4':
            raise BehaviorTreeException(
                f'{header(root.line)}BTCPP_format="{version}": only version 4 is read here')
        trees = self._collect(root, os.path.dirname(os.path.abspath(source)), set())
        main = root.attrib.get('main_tree_to_execute')
        if main is None:
            if len(trees) != 1:
                raise BehaviorTreeException(
                    '[main_tree_to_execute] was not specified correctly')
            main = next(iter(trees))
        if main not in trees:
            raise BehaviorTreeException(f'{header(root.line)}main_tree_to_execute '
                                        f"'{main}' is not a BehaviorTree of the file")
        built: list[TreeNode] = []
        try:
            node = self._tree(trees, main, blackboard, [], built)
        except BaseException:
            for made in built:  # the clients of the nodes built before the error
                close = getattr(made, 'close', None)
                if close is not None:
                    close()
            raise
        return Tree(node, blackboard, source)

    def _collect(self, root: Element, directory: str, seen: set[str]) -> dict[str, Element]:
        trees: dict[str, Element] = {}
        for element in root.children:
            if element.tag == 'BehaviorTree':
                tree_id = element.attrib.get('ID', 'MainTree')
                if len(element.children) != 1:
                    raise BehaviorTreeException(
                        f'{header(element.line)}The node <BehaviorTree> must have exactly '
                        '1 child')
                trees[tree_id] = element.children[0]
            elif element.tag == 'include':
                path = element.attrib.get('path', '')
                path = path if os.path.isabs(path) else os.path.join(directory, path)
                if path in seen:
                    continue
                seen.add(path)
                try:
                    with open(path, encoding='utf-8') as stream:
                        included = parse_xml(stream.read())
                except OSError as error:
                    raise BehaviorTreeException(
                        f'{header(element.line)}cannot include {path}: {error.strerror}'
                    ) from None
                trees.update(self._collect(included, os.path.dirname(path), seen))
            elif element.tag != 'TreeNodesModel':
                raise BehaviorTreeException(
                    f'{header(element.line)}<{element.tag}> is not a <BehaviorTree>, '
                    '<include> or <TreeNodesModel>')
        return trees

    def _tree(self, trees: dict[str, Element], tree_id: str, blackboard: Blackboard,
              stack: list[str], built: list[TreeNode]) -> TreeNode:
        if tree_id in stack:
            raise BehaviorTreeException(f"SubTree '{tree_id}' includes itself: "
                                        f"{' -> '.join([*stack, tree_id])}")
        return self._node(trees, trees[tree_id], blackboard, [*stack, tree_id], built)

    def _node(self, trees: dict[str, Element], element: Element, blackboard: Blackboard,
              stack: list[str], built: list[TreeNode]) -> TreeNode:
        attrib = dict(element.attrib)
        node_id = attrib.pop('ID', None) if element.tag in EXPLICIT_TAGS | {'SubTree'} \
            else element.tag
        if node_id is None:
            raise BehaviorTreeException(f'{header(element.line)}<{element.tag}> needs an ID')
        if element.tag == 'SubTree':
            return self._subtree(trees, element, node_id, attrib, blackboard, stack, built)
        cls = self.registry.get(node_id)
        if cls is None:
            raise BehaviorTreeException(f'{header(element.line)}Node not recognized: {node_id}')
        ports = cls.ports()
        for name, text in attrib.items():
            if name in RESERVED:
                continue
            if name not in ports:
                raise BehaviorTreeException(
                    f'{header(element.line)}a port with name [{name}] is found in the XML '
                    f'(<{node_id}>), but not in the providedPorts() of its registered node '
                    f"type (ports: {', '.join(sorted(ports)) or 'none'})")
            kind = ports[name].kind
            if reference(text) is None and kind not in (None, str):
                try:
                    kind(text)
                except ValueError as error:
                    raise BehaviorTreeException(
                        f"{header(element.line)}port [{name}] of <{node_id}>: can't convert "
                        f"'{text}': {error}") from None
        self._check_children(cls, node_id, element)
        node = cls.__new__(cls)
        node.line, node.registration_name = element.line, node_id
        node.__init__(attrib.get('name', node_id), attrib, blackboard)
        built.append(node)
        children = [self._node(trees, child, blackboard, stack, built)
                    for child in element.children]
        if isinstance(node, ControlNode):
            node.children = children
        elif isinstance(node, DecoratorNode):
            node.child = children[0]
        return node

    def _subtree(self, trees: dict[str, Element], element: Element, tree_id: str,
                 attrib: dict[str, str], blackboard: Blackboard, stack: list[str],
                 built: list[TreeNode]) -> TreeNode:
        if tree_id not in trees:
            raise BehaviorTreeException(f'{header(element.line)}SubTree ID [{tree_id}] is not '
                                        'a <BehaviorTree> of the file')
        autoremap = attrib.get('_autoremap', 'false').lower() == 'true'
        remapping = {}
        child_board = Blackboard(blackboard, remapping, autoremap)
        for key in SHARED_KEYS:
            if blackboard.has(key):
                child_board.set(key, blackboard.get(key))
        for port, text in attrib.items():
            if port in RESERVED:
                continue
            key = reference(text)
            if key is not None:
                remapping[port] = key
            else:
                child_board.set(port, text)  # a literal: the subtree sees the string
        child_board.remapping = remapping
        node = SubTreeNode(attrib.get('name', tree_id), attrib, child_board)
        node.line, node.registration_name = element.line, 'SubTree'
        node.child = self._tree(trees, tree_id, child_board, stack, built)
        return node

    @staticmethod
    def _check_children(cls: type[TreeNode], node_id: str, element: Element) -> None:
        count = len(element.children)
        if issubclass(cls, ControlNode) and count == 0:
            raise BehaviorTreeException(
                f'{header(element.line)}A Control node must have at least 1 child: <{node_id}>')
        if issubclass(cls, DecoratorNode) and count != 1:
            raise BehaviorTreeException(
                f'{header(element.line)}The node <{node_id}> must have exactly 1 child')
        if not issubclass(cls, (ControlNode, DecoratorNode)) and count:
            raise BehaviorTreeException(
                f'{header(element.line)}The node <{node_id}> must not have any child')
