"""`topic echo`'s subscription, whose QoS follows the topic's publishers.

ros2cli chooses the QoS once, from the publishers its node knows when it subscribes. A node
that has just joined may not know them yet (their endpoints arrive some time after their
participant, seen: 2 in 5 echos of a latched topic in a fresh domain subscribed volatile and
printed nothing). So here the choice is made again whenever a publisher appears that was not
there before, and the subscription is re-created when the compatible profile has changed: a
transient-local publisher then hands its history to the new subscription, as it would have
to the first one had it been seen in time. Policies given on the command line
(`--qos-durability`, ...) are the user's: no adaptation then, as in ros2cli.

The new subscription is made before the old one goes, so nothing published meanwhile is
lost; a message both deliver (or a transient-local history that repeats what the old one
printed) is passed on once, recognised by its source timestamp and publication sequence
number.

A replacement subscription catches up on the publisher's history while the old one has already
printed it; a history sample the writer drops meanwhile (KEEP_LAST: the next publish pushes it
out before the new reader has fetched it) comes as a message-lost event for a message the echo
showed. So a subscription's lost events until CATCH_UP after its first message are not
reported: they concern history, which a late subscriber is never promised (a volatile ros2cli
echo never hears of it). The first subscription too: a transient-local reliable echo of a
publisher whose KEEP_LAST history moved on while the echo fetched it was told of the samples
it never had (seen: 'A message was lost!!!' before the one message of `echo --once`).
The window is needed, not just "before the first message": the gap
notice and the next message arrive together, and rclpy's executor runs subscriptions first.
"""

from __future__ import annotations

import argparse
import time
from collections import deque
from collections.abc import Callable
from typing import Any

from ros2cli.verb_context import VerbContext

from ros2topic.api.qos import (
    compatible_profile,
    policies_given,
    qos_profile_from_args,
    subscription_events,
)

SEEN_KEPT = 4096  # message keys remembered to drop a repeat (deeper than any usual history)
POLL_PERIOD = 0.05  # seconds between two looks at the publishers (cheap: the local cache)
CATCH_UP = 1.0  # seconds after a subscription's first message in which its losses are history


class AdaptiveSubscription:
    """One subscription of `node` to `topic`, re-created with a compatible QoS when a new
    publisher asks for it; call poll() between spins."""

    def __init__(self, node: Any, msg_type: Any, topic: str,
                 callback: Callable[[Any, Any], None], args: argparse.Namespace,
                 context: VerbContext, *, raw: bool = False,
                 message_lost: Callable[[Any], None] | None = None) -> None:
        self.node = node
        self.context = context
        self.msg_type = msg_type
        self.topic = topic
        self.callback = callback
        self.args = args
        self.raw = raw
        self.message_lost = message_lost
        self.fixed = policies_given(args)
        self._said: set[str] = set()  # ros2cli's fallback notices, each printed once
        self._seen: deque[tuple[int, int]] = deque()
        self._seen_set: set[tuple[int, int]] = set()
        infos = [] if self.fixed else node.get_publishers_info_by_topic(topic)
        self._publishers = {bytes(info.endpoint_gid) for info in infos}
        self.profile = self._choose(infos)
        self.subscription = self._create(self.profile)
        self._looked = time.monotonic()

    def _choose(self, infos: list[Any]) -> Any:
        profile = qos_profile_from_args(self.args)
        if self.fixed:
            return profile
        return compatible_profile(profile, infos, self._say)

    def _say(self, text: str) -> None:
        if text not in self._said:
            self._said.add(text)
            print(text, flush=True, file=self.context.stdout)

    def _create(self, profile: Any) -> Any:
        from rclpy.event_handler import UnsupportedEventTypeError

        events = subscription_events(self.node, self.topic, self.context,
                                     superseded=self._would_change)
        first: list[float] = []  # monotonic time of the subscription's first message
        if self.message_lost is not None:
            report = self.message_lost

            def lost(status: Any) -> None:
                if first and time.monotonic() - first[0] >= CATCH_UP:
                    report(status)
            events.message_lost = lost
        deliver = self._noting_first(first)
        try:
            return self.node.create_subscription(self.msg_type, self.topic, deliver,
                                                 profile, event_callbacks=events, raw=self.raw)
        except UnsupportedEventTypeError:  # an RMW without the message-lost event
            events.message_lost = None
            return self.node.create_subscription(self.msg_type, self.topic, deliver,
                                                 profile, event_callbacks=events, raw=self.raw)

    def _noting_first(self, first: list[float]) -> Callable[[Any, Any], None]:
        """_deliver, noting in `first` when the subscription delivered its first message."""
        def deliver(msg: Any, info: Any) -> None:
            if not first:
                first.append(time.monotonic())
            self._deliver(msg, info)
        return deliver

    def _deliver(self, msg: Any, info: Any) -> None:
        if not self.fixed:
            key = (info['source_timestamp'], info.get('publication_sequence_number', 0))
            if key in self._seen_set:
                return
            self._seen.append(key)
            self._seen_set.add(key)
            if len(self._seen) > SEEN_KEPT:
                self._seen_set.discard(self._seen.popleft())
        self.callback(msg, info)

    def _appeared(self) -> tuple[list[Any], bool]:
        """(the publishers now, whether one of them was not there at the last look)."""
        infos = self.node.get_publishers_info_by_topic(self.topic)
        gids = {bytes(info.endpoint_gid) for info in infos}
        return infos, not gids <= self._publishers

    def _would_change(self) -> bool:
        """Whether the publishers known now call for another profile (the incompatible-QoS
        warning of a subscription about to be replaced is not shown)."""
        if self.fixed:
            return False
        infos, _ = self._appeared()
        quiet = compatible_profile(qos_profile_from_args(self.args), infos, lambda _text: None)
        return _differs(quiet, self.profile)

    def poll(self) -> None:
        """Re-decide the QoS if a publisher has appeared; re-subscribe if it changed."""
        if self.fixed or time.monotonic() - self._looked < POLL_PERIOD:
            return
        self._looked = time.monotonic()
        infos, appeared = self._appeared()
        self._publishers = {bytes(info.endpoint_gid) for info in infos}
        if not appeared:
            return
        profile = self._choose(infos)
        if not _differs(profile, self.profile):
            return
        old = self.subscription
        self.profile = profile
        self.subscription = self._create(profile)
        self.node.destroy_subscription(old)


def _differs(one: Any, other: Any) -> bool:
    return (one.reliability, one.durability) != (other.reliability, other.durability)
