"""The rosbag2_player node: publishers (or service clients) fed at the recorded pace.

Messages go out as the recorded CDR bytes (raw publishing), with the QoS their publishers
offered while recording (rosbag2's adapt_offer_to_recorded_offers) unless overridden. Unlike
Jazzy, each publisher first waits (at most DISCOVERY_BOUND seconds) until the subscribers
already in the graph have matched it, so the first messages of a bag are not lost to
discovery. `rosbag2_py.Player` and `ros2 bag play` run it.
"""

from __future__ import annotations

import threading
import time
from typing import Any

from ros2cli.interface_types import import_type
from ros2cli.node.discovery import wait_for_graph

from rosbag2_py._bag_files import BagReader
from rosbag2_py._metadata_io import (
    BagError,
    event_topic,
    is_service_event_topic,
    offer_qos_for_recorded,
    service_name,
    service_type,
)
from rosbag2_py._playback_clock import PlaybackClock
from rosbag2_py._player_services import PlayerServices, Steps
from rosbag2_py._session import SpaceKey
from rosbag2_py._storage import StorageFilter, filter_selects

DISCOVERY_BOUND = 4.0  # seconds to wait for known subscribers to match a new publisher
MATCH_SETTLE = 0.6  # seconds the graph must stay unchanged and matched before playing
ACK_BOUND = 2.0  # seconds to wait at the end for reliable subscribers to acknowledge


def _absolute(name: str) -> str:
    return name if name.startswith('/') else '/' + name


def _remaps(arguments: list[str]) -> dict[str, str]:
    """`old:=new` pairs of PlayOptions.topic_remapping_options (ROS arguments or bare pairs)."""
    pairs = (a.split(':=', 1) for a in arguments if ':=' in a)
    return {_absolute(old): _absolute(new) for old, new in pairs}


class PlayerNode:
    """What a playback does with its node; `options` is a rosbag2_py.PlayOptions."""

    def __init__(self, node: Any, reader: BagReader, options: Any, burst: int | None = None):
        self.node = node
        self.log = node.get_logger()
        self.reader = reader
        self.options = options
        self.burst = burst  # messages to publish at once (0: all), None: play in time
        self.finished = threading.Event()
        self.keys = SpaceKey(self.toggle_paused)
        self.remaps = _remaps(options.topic_remapping_options)
        self.clock_topics = {_absolute(t) for t in options.clock_topics}
        self.overrides = dict(options.topic_qos_profile_overrides)
        self.publishers: dict[str, Any] = {}
        self.clients: dict[str, tuple[Any, Any]] = {}
        self.warned: set[str] = set()
        self.pending: list[Any] = []  # service requests sent, answers not yet seen
        self.clock_publisher: Any = None
        self.first_stamp = reader.meta.starting_time_ns + int(options.start_offset * 1e9)
        self.clock = PlaybackClock(self.first_stamp, options.rate,
                                   options.start_paused and burst is None)
        self.started = False
        self.until = self._until()
        # Requests of the player's services, taken by the playing loop.
        self.seek_to: int | None = None
        self.steps = Steps()  # ~/play_next, ~/burst: messages to publish at once while paused

    def _until(self) -> int:
        """The last receive stamp to play (-1: all), from playback_duration/until_timestamp."""
        duration = self.options.playback_duration
        until = int(self.options.playback_until_timestamp)
        if duration < 0 and until < 0:
            return -1
        from_duration = 0 if duration == 0 else self.first_stamp + int(duration * 1e9)
        return max(from_duration, until)

    # ---- bag time (what /clock says) ----
    def bag_now(self) -> int:
        """The bag time; before playing starts (discovery, --delay) the bag's first stamp."""
        return self.clock.now() if self.started else self.first_stamp

    def _publish_clock(self, stamp: int) -> None:
        from rosgraph_msgs.msg import Clock

        message = Clock()
        message.clock.sec, message.clock.nanosec = divmod(stamp, 1_000_000_000)
        self.clock_publisher.publish(message)

    def _start_clock(self, stop: threading.Event) -> None:
        """/clock publisher (rclcpp's ClockQoS: best effort, depth 1) and, with a frequency,
        the thread that publishes the bag time at that rate until playing ends."""
        from rclpy.qos import QoSProfile, ReliabilityPolicy
        from rosgraph_msgs.msg import Clock

        frequency = float(self.options.clock_publish_frequency)
        if frequency <= 0.0 and not self.options.clock_publish_on_topic_publish:
            return
        self.clock_publisher = self.node.create_publisher(
            Clock, '/clock', QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT))
        if frequency > 0.0:
            def tick() -> None:
                while not stop.wait(1.0 / frequency) and not self.finished.is_set():
                    self._publish_clock(self.bag_now())
            threading.Thread(target=tick, daemon=True, name='clock').start()

    # ---- pause ----
    @property
    def paused(self) -> bool:
        return self.clock.paused

    def toggle_paused(self) -> None:
        if self.clock.resume():
            self.log.info('Resuming play.')
        elif self.clock.pause():
            self.log.info('Pausing play.')

    # ---- endpoints ----
    def _selected(self) -> set[str]:
        options = self.options
        rule = StorageFilter(
            topics=[_absolute(t) for t in options.topics_to_filter],
            services_events=[event_topic(s) for s in options.services_to_filter],
            regex=options.regex_to_filter,
            exclude_topics=[_absolute(t) for t in options.exclude_topics_to_filter],
            exclude_service_events=[event_topic(s)
                                    for s in options.exclude_service_events_to_filter],
            regex_to_exclude=options.exclude_regex_to_filter)
        return {t.name for t in self.reader.meta.topics if filter_selects(rule, t.name)}

    def _create_endpoints(self, selected: set[str]) -> None:
        for topic in self.reader.meta.topics:
            if topic.name not in selected:
                continue
            is_event = is_service_event_topic(topic.name, topic.type)
            try:
                if is_event and self.options.publish_service_requests:
                    srv_class = import_type(service_type(topic.type), 'srv')
                    event_class = import_type(topic.type, 'srv')
                    name = self.remaps.get(service_name(topic.name), service_name(topic.name))
                    self.clients[topic.name] = (
                        self.node.create_client(srv_class, name), event_class)
                    continue
                kind = 'srv' if is_event else 'msg'
                msg_class = import_type(topic.type, kind)
            except ValueError:
                self.log.warn(f"Topic '{topic.name}' has type '{topic.type}', which is not "
                              'installed here: not played')
                continue
            name = self.remaps.get(topic.name, topic.name)
            qos = self.overrides.get(name, self.overrides.get(topic.name))
            if qos is None:
                qos = offer_qos_for_recorded(topic.offered_qos_profiles)
            self.publishers[topic.name] = self.node.create_publisher(msg_class, name, qos)

    def _wait_for_subscribers(self) -> None:
        """Until the graph is known and its subscribers have matched our endpoints (bounded).

        The `ros2` daemon's settled graph says how many subscribers each topic has: a fresh
        player may not have discovered them yet, and would otherwise play to nobody.
        """
        from ros2cli.graph import get_graph
        from ros2cli.verb_context import CliError
        try:
            graph = get_graph(detail=False)
            expected = {p.topic_name: graph.topic_counts(p.topic_name)[1]
                        for p in self.publishers.values()}
        except CliError:  # no daemon to ask: rely on our own discovery alone
            expected = {}

        def matched() -> bool:
            return all(p.get_subscription_count() >= max(
                expected.get(p.topic_name, 0), self.node.count_subscribers(p.topic_name))
                       for p in self.publishers.values()) and all(
                c.service_is_ready() for c, _ in self.clients.values())

        # The settle time also covers the other side: a subscriber may match our publisher
        # some hundred milliseconds after we matched it, and drops what comes before.
        wait_for_graph(self.node, matched, settle=MATCH_SETTLE, bound=DISCOVERY_BOUND)

    # ---- playing ----
    def run(self, stop: threading.Event) -> str | None:
        self.log.info(f'Set rate to {self.options.rate:g}')
        if not self.options.disable_keyboard_controls and self.keys.active:
            self.log.info('Adding keyboard callbacks.')
            self.log.info('Press SPACE for Pause/Resume')
            self.keys.start()
        try:
            self._create_endpoints(self._selected())
            self._start_clock(stop)
            self.log.info(f'Playback until timestamp: {self.until}')
            # A paused start leaves discovery the time until resumed; a bag with nothing to
            # publish waits for nobody.
            counts = {t.name: t.message_count for t in self.reader.meta.topics}
            if not self.paused and any(counts.get(name) for name in
                                       (*self.publishers, *self.clients)):
                self._wait_for_subscribers()
            services = PlayerServices(self, stop)
            try:
                while True:
                    self._play_once(stop)
                    if stop.is_set() or not self.options.loop:
                        break
            finally:
                self.finished.set()  # /clock stops with the last message
                self.steps.wake()
                services.close()
            self._wait_for_acks()
        except BagError as error:
            return str(error)
        finally:
            self.finished.set()
            self.keys.close()
        return None

    def _delay(self, stop: threading.Event) -> bool:
        """The --delay before each loop, in wall time; False on stop."""
        return not stop.wait(self.options.delay) if self.options.delay > 0 else True

    def _play_once(self, stop: threading.Event) -> None:
        if not self._delay(stop):
            return
        self.clock.jump(self.first_stamp)
        self.started = True
        selected = set(self.publishers) | set(self.clients)
        start, sent = self.first_stamp, 0
        while True:
            for topic, stamp, data in self.reader.messages(selected, start_ns=start):
                if 0 <= self.until < stamp:
                    return
                if self.burst is not None:
                    if stop.is_set() or (self.burst and sent >= self.burst):
                        return
                elif not self.clock.sleep_until(stamp, lambda: stop.is_set() or (
                        self.seek_to is not None or self.steps.wanted())):
                    if stop.is_set():
                        return
                    if self.seek_to is not None:
                        break  # read again from the seek point
                    self.clock.jump(stamp)  # play_next/burst: this message now, still paused
                self._publish_now(topic, stamp, data)
                sent += 1
                self.steps.published()
            else:
                return
            start, self.seek_to = int(self.seek_to), None
            self.clock.jump(start)

    def _publish_now(self, topic: str, stamp: int, data: bytes) -> None:
        if self.clock_publisher is not None and self.options.clock_publish_on_topic_publish \
                and (not self.options.clock_topics or topic in self.clock_topics):
            self._publish_clock(stamp)
        self._publish(topic, data)

    def _publish(self, topic: str, data: bytes) -> None:
        publisher = self.publishers.get(topic)
        if publisher is not None:
            publisher.publish(data)
            return
        client, event_class = self.clients[topic]
        from rclpy.serialization import deserialize_message
        from service_msgs.msg import ServiceEventInfo

        event = deserialize_message(data, event_class)
        wanted = (ServiceEventInfo.REQUEST_RECEIVED
                  if int(self.options.service_requests_source) == 0
                  else ServiceEventInfo.REQUEST_SENT)
        if event.info.event_type != wanted:
            return
        if not event.request:
            if topic not in self.warned:
                self.warned.add(topic)
                self.log.warn("Can't send service request. The configuration of "
                              f"introspection for '{client.srv_name}' was metadata only!")
            return
        if not client.service_is_ready():
            self.log.error("Service request hasn't been sent. The "
                           f"'{client.srv_name}' service isn't ready !")
            return
        self.pending.append(client.call_async(event.request[0]))

    def _wait_for_acks(self) -> None:
        from rclpy.duration import Duration

        # Unlike Jazzy, which waits only when asked (--wait-for-all-acked), a bounded wait is
        # the default: a short bag would otherwise end before a reliable subscriber has it.
        bound = self.options.wait_acked_timeout
        deadline = time.monotonic() + (bound / 1000.0 if bound >= 0 else ACK_BOUND)
        if self.pending:
            # Spinning takes the answers in: a request is only sure to have arrived then.
            from ros2cli.node.direct import spin_once
            while not all(f.done() for f in self.pending) and time.monotonic() < deadline:
                spin_once(self.node, 0.05)
        for publisher in self.publishers.values():
            left = deadline - time.monotonic()
            if left <= 0:
                break
            try:
                publisher.wait_for_all_acked(Duration(nanoseconds=int(left * 1e9)))
            except Exception:  # best effort publishers have nothing to ack
                pass
