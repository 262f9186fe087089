"""Control nodes: BT.CPP v4's Sequence/Fallback family and Nav2's PipelineSequence,
RecoveryNode and RoundRobin, with the tick and halt rules of their upstream classes."""

from __future__ import annotations

from nav2_behavior_tree.core import BehaviorTreeException, ControlNode, InputPort, NodeStatus, ports

S, F, R, SKIP = NodeStatus.SUCCESS, NodeStatus.FAILURE, NodeStatus.RUNNING, NodeStatus.SKIPPED


class _Memory(ControlNode):
    """Sequence and Fallback: resume at the running child; `stop` ends the node."""

    STOP = F  # the child status that ends the node with that status
    RESET_ON_STOP = True

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.current = 0
        self.all_skipped = True

    def tick(self) -> NodeStatus:
        if self.status == NodeStatus.IDLE:
            self.all_skipped = True
        self.status = R
        while self.current < len(self.children):
            child_status = self.children[self.current].execute_tick()
            self.all_skipped &= child_status == SKIP
            if child_status == R:
                return R
            if child_status == self.STOP:
                self.halt_children()
                if self.RESET_ON_STOP:
                    self.current = 0
                return self.STOP
            self.current += 1
        self.halt_children()
        self.current = 0
        return SKIP if self.all_skipped else (S if self.STOP == F else F)

    def halt(self) -> None:
        self.current = 0
        super().halt()


class Sequence(_Memory):
    STOP = F


class SequenceWithMemory(_Memory):
    """A failed child is ticked again next time (the earlier ones are not)."""

    STOP = F
    RESET_ON_STOP = False


class Fallback(_Memory):
    STOP = S


class _Reactive(ControlNode):
    """ReactiveSequence/ReactiveFallback: every tick starts again at the first child."""

    STOP = F

    def tick(self) -> NodeStatus:
        all_skipped = True
        self.status = R
        for index, child in enumerate(self.children):
            child_status = child.execute_tick()
            all_skipped &= child_status == SKIP
            if child_status == R:
                # A later child left running stops. BT.CPP also resets the earlier ones to
                # IDLE here, which makes Nav2's GoalUpdated (it remembers the goal while
                # active) forget the goal every tick and never fire: they keep their status.
                self.halt_children(index + 1)
                return R
            if child_status == self.STOP:
                self.halt_children()
                return self.STOP
            if child_status == SKIP:
                self.halt_child(index)
        self.halt_children()
        return SKIP if all_skipped else (S if self.STOP == F else F)


class ReactiveSequence(_Reactive):
    STOP = F


class ReactiveFallback(_Reactive):
    STOP = S


class PipelineSequence(ControlNode):
    """Nav2: ticks every child up to the furthest one running so far; all keep running."""

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.last_child_ticked = 0

    def tick(self) -> NodeStatus:
        skipped = 0
        for index, child in enumerate(self.children):
            child_status = child.execute_tick()
            if child_status == F:
                self.halt_children()
                self.last_child_ticked = 0
                return F
            if child_status == SKIP:
                skipped += 1
            elif child_status == R and index >= self.last_child_ticked:
                self.last_child_ticked = index
                return R
        self.halt_children()
        self.last_child_ticked = 0
        return SKIP if skipped == len(self.children) else S

    def halt(self) -> None:
        super().halt()
        self.last_child_ticked = 0


class RecoveryNode(ControlNode):
    """Nav2: child 0 is the action, child 1 its recovery, retried number_of_retries times."""

    PORTS = ports(number_of_retries=InputPort(int, 1, 'Number of retries'))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.current = 0
        self.retry_count = 0

    def tick(self) -> NodeStatus:
        retries = self.get_input('number_of_retries')
        if len(self.children) != 2:
            raise BehaviorTreeException(
                f"Recovery Node '{self.name}' must only have 2 children.")
        self.status = R
        while self.current < 2 and self.retry_count <= retries:
            child_status = self.children[self.current].execute_tick()
            if self.current == 0:
                if child_status == SKIP:
                    self.halt()
                    return SKIP
                if child_status == S:
                    self.halt_child(1)
                    self.halt()
                    return S
                if child_status == R:
                    return R
                if self.retry_count < retries:  # FAILURE: try the recovery
                    self.halt_child(0)
                    self.current = 1
                    continue
                self.halt()
                return F
            if child_status == SKIP:
                self.current = 0
                self.halt_child(1)
                return F
            if child_status == R:
                return R
            if child_status == S:
                self.halt_child(1)
                self.retry_count += 1
                self.current = 0
                continue
            self.halt()
            return F
        self.halt()
        return F

    def halt(self) -> None:
        super().halt()
        self.retry_count = 0
        self.current = 0


class RoundRobin(ControlNode):
    """Nav2: each tick resumes at the child after the last one that finished."""

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.current = 0
        self.failed = 0

    def tick(self) -> NodeStatus:
        count = len(self.children)
        self.status = R
        skipped = 0
        while self.failed + skipped < count:
            child_status = self.children[self.current].execute_tick()
            if child_status != R:
                self.current = (self.current + 1) % count
            if child_status == S:
                self.failed = 0
                self.halt_children()
                return S
            if child_status == F:
                self.failed += 1
            elif child_status == SKIP:
                skipped += 1
            else:
                return R
        all_skipped = skipped == count
        self.halt()
        return SKIP if all_skipped else F

    def halt(self) -> None:
        super().halt()
        self.current = 0
        self.failed = 0


CONTROL_NODES = {cls.__name__: cls for cls in (
    Sequence, SequenceWithMemory, Fallback, ReactiveSequence, ReactiveFallback,
    PipelineSequence, RecoveryNode, RoundRobin)}
CONTROL_NODES['SequenceStar'] = SequenceWithMemory  # BT.CPP v3's name, still accepted
