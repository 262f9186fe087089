"""nav2_behavior_tree's pure logic: the BehaviorTree.CPP v4 XML reader and the tick rules
of the control nodes and decorators, on tiny trees of scripted test leaves (no ROS)."""

from __future__ import annotations

import time
from pathlib import Path
from typing import ClassVar

import pytest
from nav2_behavior_tree.behavior_tree_engine import BehaviorTreeEngine, BtStatus
from nav2_behavior_tree.conditions import PLANNER_RECOVERABLE
from nav2_behavior_tree.core import (
    ActionNode,
    BehaviorTreeException,
    Blackboard,
    InputPort,
    NodeStatus,
    OutputPort,
    ports,
)

S, F, R = NodeStatus.SUCCESS, NodeStatus.FAILURE, NodeStatus.RUNNING
LOG: list[str] = []


class Script(ActionNode):
    """Answers the statuses of `script` ('S', 'F', 'R'), one per tick, the last one forever;
    logs 'name:status' per tick and 'name:halt' when halted while running."""

    PORTS = ports(script=InputPort(str, 'S'), out=OutputPort(), value=InputPort(int, 0))
    CODES: ClassVar[dict[str, NodeStatus]] = {'S': S, 'F': F, 'R': R}

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.ticks = 0

    def tick(self) -> NodeStatus:
        script = self.get_input('script')
        status = self.CODES[script[min(self.ticks, len(script) - 1)]]
        self.ticks += 1
        LOG.append(f'{self.name}:{status.name[0]}')
        self.set_output('out', self.get_input('value'))
        return status

    def halt(self) -> None:
        LOG.append(f'{self.name}:halt')
        super().halt()


def tree(body: str, blackboard: Blackboard | None = None, extra: str = ''):
    LOG.clear()
    engine = BehaviorTreeEngine({'Script': Script}, with_ros=False)
    xml = (f'<root BTCPP_format="4" main_tree_to_execute="MainTree">\n'
           f'<BehaviorTree ID="MainTree">\n{body}\n</BehaviorTree>{extra}\n</root>')
    return engine, engine.create_tree_from_text(xml, blackboard or Blackboard())


def ticks(t, count: int) -> list[NodeStatus]:
    return [t.tick_once() for _ in range(count)]


def test_unknown_node_names_itself_and_its_line():
    with pytest.raises(BehaviorTreeException) as error:
        tree('<Sequence>\n  <Script/>\n  <Teleport where="moon"/>\n</Sequence>')
    assert str(error.value) == 'Error at line 5: -> Node not recognized: Teleport'


def test_bad_ports_children_and_main_tree_are_named():
    with pytest.raises(BehaviorTreeException, match=r'line 3: -> a port with name \[hzz\]'):
        tree('<RateController hzz="1"><Script/></RateController>')
    with pytest.raises(BehaviorTreeException, match=r"line 3: .*\[hz\].*can't convert 'fast'"):
        tree('<RateController hz="fast"><Script/></RateController>')
    with pytest.raises(BehaviorTreeException, match='must have exactly 1 child'):
        tree('<Inverter><Script/><Script/></Inverter>')
    with pytest.raises(BehaviorTreeException, match='must not have any child'):
        tree('<Script><Script/></Script>')
    with pytest.raises(BehaviorTreeException, match='Error parsing the XML'):
        tree('<Sequence><Script></Sequence>')
    engine = BehaviorTreeEngine(with_ros=False)
    with pytest.raises(BehaviorTreeException, match="main_tree_to_execute 'Main'"):
        engine.create_tree_from_text('<root BTCPP_format="4" main_tree_to_execute="Main">'
                                     '<BehaviorTree ID="X"><AlwaysSuccess/></BehaviorTree>'
                                     '</root>', Blackboard())


def test_ports_read_literals_and_blackboard_and_subtrees_remap():
    board = Blackboard()
    board.set('wanted', 7)
    _, t = tree('<Sequence><Script name="a" value="{wanted}" out="{got}"/>'
                '<SubTree ID="Inner" inner_value="5" result="{from_inner}"/>'
                '<SubTree ID="Auto" _autoremap="true"/></Sequence>', board,
                extra='<BehaviorTree ID="Inner"><Script name="b" value="{inner_value}" '
                      'out="{result}"/></BehaviorTree>'
                      '<BehaviorTree ID="Auto"><Script name="c" value="{wanted}" '
                      'out="{@rooted}"/></BehaviorTree>')
    assert t.tick_once() == S
    assert board.get('got') == 7
    assert board.get('from_inner') == 5  # the literal '5' converted by the port's type
    assert board.get('result') is None  # the subtree's key stayed in the subtree
    assert board.get('rooted') == 7
    # Nav2's handles and timeouts reach the leaves of a subtree that does not remap them
    board.set('server_timeout', 0.25)
    _, t = tree('<SubTree ID="Inner" result="{timeout}"/>', board,
                extra='<BehaviorTree ID="Inner"><Script value="{server_timeout}" '
                      'out="{result}"/></BehaviorTree>')
    assert t.tick_once() == S and board.get('timeout') == 0.25


def test_sequence_resumes_at_the_running_child_and_fallback_stops_at_success():
    _, t = tree('<Sequence><Script name="a"/><Script name="b" script="RS"/></Sequence>')
    assert ticks(t, 2) == [R, S]
    assert LOG == ['a:S', 'b:R', 'b:S']  # a was not ticked again
    _, t = tree('<Fallback><Script name="a" script="F"/><Script name="b"/>'
                '<Script name="c"/></Fallback>')
    assert t.tick_once() == S
    assert LOG == ['a:F', 'b:S']


def test_reactive_sequence_ticks_conditions_again_and_halts_the_running_child():
    _, t = tree('<ReactiveSequence><Script name="cond" script="SSF"/>'
                '<Script name="act" script="R"/></ReactiveSequence>')
    assert ticks(t, 3) == [R, R, F]
    assert LOG == ['cond:S', 'act:R', 'cond:S', 'act:R', 'cond:F', 'act:halt']


def test_pipeline_sequence_keeps_earlier_children_ticking():
    _, t = tree('<PipelineSequence><Script name="a" script="SR"/><Script name="b" '
                'script="RRS"/></PipelineSequence>')
    assert ticks(t, 3) == [R, R, S]  # the last child's success ends it, a is halted
    assert LOG == ['a:S', 'b:R', 'a:R', 'b:R', 'a:R', 'b:S', 'a:halt']
    LOG.clear()
    _, t = tree('<PipelineSequence><Script name="a" script="RF"/><Script name="b" '
                'script="R"/></PipelineSequence>')
    assert ticks(t, 2) == [R, F]
    assert LOG == ['a:R', 'a:F']


def test_recovery_node_retries_after_a_successful_recovery_then_gives_up():
    _, t = tree('<RecoveryNode number_of_retries="2"><Script name="act" script="F"/>'
                '<Script name="fix"/></RecoveryNode>')
    assert t.tick_once() == F
    assert LOG == ['act:F', 'fix:S', 'act:F', 'fix:S', 'act:F']
    _, t = tree('<RecoveryNode number_of_retries="3"><Script name="act" script="FS"/>'
                '<Script name="fix" script="R"/></RecoveryNode>')
    assert t.tick_once() == R  # recovery running
    assert LOG == ['act:F', 'fix:R']
    _, t = tree('<RecoveryNode><Script name="act" script="F"/>'
                '<Script name="fix" script="F"/></RecoveryNode>')
    assert t.tick_once() == F
    assert LOG == ['act:F', 'fix:F']


def test_round_robin_resumes_after_the_last_child_that_ended():
    _, t = tree('<RoundRobin><Script name="a" script="F"/><Script name="b"/>'
                '<Script name="c"/></RoundRobin>')
    assert ticks(t, 3) == [S, S, S]
    assert LOG == ['a:F', 'b:S', 'c:S', 'a:F', 'b:S']
    _, t = tree('<RoundRobin><Script name="a" script="F"/><Script name="b" script="F"/>'
                '</RoundRobin>')
    assert t.tick_once() == F


def test_decorators():
    _, t = tree('<Inverter><Script script="F"/></Inverter>')
    assert t.tick_once() == S
    _, t = tree('<RetryUntilSuccessful num_attempts="3"><Script name="x" script="FFS"/>'
                '</RetryUntilSuccessful>')
    assert t.tick_once() == S and LOG == ['x:F', 'x:F', 'x:S']
    _, t = tree('<RetryUntilSuccessful num_attempts="2"><Script name="x" script="F"/>'
                '</RetryUntilSuccessful>')
    assert t.tick_once() == F and len(LOG) == 2
    _, t = tree('<KeepRunningUntilFailure><Script script="SSF"/></KeepRunningUntilFailure>')
    assert ticks(t, 3) == [R, R, F]


def test_rate_controller_ticks_its_child_once_per_period():
    _, t = tree('<RateController hz="20"><Script name="x"/></RateController>')
    assert t.tick_once() == S  # the first tick goes through
    assert t.tick_once() == R and LOG == ['x:S']  # within the period: waiting (RUNNING)
    time.sleep(0.06)
    t.tick_once()
    assert LOG == ['x:S', 'x:S']


def test_goal_updated_and_error_code_conditions():
    board = Blackboard()
    board.set('goal', 'first')
    board.set('code', 0)
    _, t = tree('<ReactiveFallback><GoalUpdated/><Script name="w" script="R"/>'
                '</ReactiveFallback>', board)
    assert ticks(t, 2) == [R, R]
    board.set('goal', 'second')
    assert t.tick_once() == S
    assert LOG[-1] == 'w:halt'
    _, t = tree('<WouldAPlannerRecoveryHelp error_code="{code}"/>', board)
    assert t.tick_once() == F
    board.set('code', 208)  # NO_VALID_PATH
    assert t.tick_once() == S and 208 in PLANNER_RECOVERABLE
    board.set('code', 201)  # INVALID_PLANNER: no recovery helps
    assert t.tick_once() == F


def test_engine_runs_until_done_and_halts_on_cancel():
    engine, t = tree('<Sequence><Script name="a" script="RRS"/></Sequence>')
    loops: list[int] = []
    assert engine.run(t, lambda: loops.append(1), lambda: False, 0.001) == BtStatus.SUCCEEDED
    assert len(loops) == 3
    engine, t = tree('<Script name="a" script="R"/>')
    assert engine.run(t, lambda: None, lambda: len(LOG) >= 2, 0.001) == BtStatus.CANCELED
    assert LOG == ['a:R', 'a:R', 'a:halt']
    engine, t = tree('<RecoveryNode><Script/><Script/><Script/></RecoveryNode>')
    failures: list[str] = []
    engine.log = failures.append
    assert engine.run(t, lambda: None, lambda: False, 0.001) == BtStatus.FAILED
    assert failures == ["Behavior tree threw exception: Recovery Node 'RecoveryNode' must only "
                        'have 2 children.. Exiting with failure.']


def test_the_installed_trees_use_only_known_nodes_and_ports():
    from ament_index_python.packages import get_package_share_directory
    from nav2_behavior_tree.behavior_tree_engine import builtin_nodes
    from nav2_behavior_tree.xml_parser import RESERVED, parse_xml

    registry = builtin_nodes()
    folder = Path(get_package_share_directory('nav2_bt_navigator')) / 'behavior_trees'
    trees = sorted(folder.glob('*.xml'))
    assert [t.name for t in trees] == [
        'follow_point.xml', 'navigate_through_poses_w_replanning_and_recovery.xml',
        'navigate_to_pose_w_replanning_and_recovery.xml', 'navigate_w_replanning_distance.xml',
        'navigate_w_replanning_only_if_goal_is_updated.xml', 'navigate_w_replanning_speed.xml',
        'navigate_w_replanning_time.xml', 'odometry_calibration.xml']
    for tree_file in trees:
        root = parse_xml(tree_file.read_text())
        assert root.attrib == {'BTCPP_format': '4', 'main_tree_to_execute': 'MainTree'}
        elements = [root.children[0].children[0]]
        seen = set()
        while elements:
            element = elements.pop()
            elements.extend(element.children)
            ports = registry[element.tag].ports()
            assert set(element.attrib) - RESERVED <= set(ports), (tree_file.name, element.tag)
            seen.add(element.tag)
        if 'recovery' not in tree_file.name:
            continue
        assert {'ComputePathToPose', 'ComputePathThroughPoses'} & seen
        assert {'FollowPath', 'Spin', 'Wait', 'BackUp', 'ClearEntireCostmap', 'GoalUpdated',
                'RoundRobin', 'PipelineSequence', 'RateController'} <= seen


def test_status_changes_reach_an_observer():
    _, t = tree('<Sequence name="seq"><Script name="a"/><Script name="b" script="RS"/>'
                '</Sequence>')
    changes = []
    for node in t.nodes:
        node.observer = lambda n, old, new: changes.append((n.name, old.name, new.name))
    ticks(t, 2)
    assert changes == [('seq', 'IDLE', 'RUNNING'), ('a', 'IDLE', 'SUCCESS'),
                       ('b', 'IDLE', 'RUNNING'), ('b', 'RUNNING', 'SUCCESS'),
                       ('a', 'SUCCESS', 'IDLE'), ('b', 'SUCCESS', 'IDLE'),
                       ('seq', 'RUNNING', 'SUCCESS')]
