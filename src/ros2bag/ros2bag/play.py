"""ros2 bag play: publish a bag's messages again, with their recorded timing.

Messages go out as the recorded CDR bytes (raw publishing), with the QoS their publishers
offered while recording (rosbag2's adapt_offer_to_recorded_offers). Unlike Jazzy, each
publisher first waits (at most DISCOVERY_BOUND seconds) until the subscribers already in the
graph have matched it, so the first messages of a bag are not lost to discovery.
"""

from __future__ import annotations

import argparse
import threading
import time
from typing import Any

from ros2cli_lite.api import import_type
from ros2cli_lite.node import wait_for_graph

from ros2bag.metadata import (
    BagError,
    is_service_event_topic,
    offer_qos_for_recorded,
    service_name,
    service_type,
)
from ros2bag.session import SpaceKey, ros_node
from ros2bag.storage import STORAGES, BagReader

DISCOVERY_BOUND = 4.0  # seconds to wait for known subscribers to match a new publisher
MATCH_SETTLE = 0.6  # seconds the graph must stay unchanged and matched before playing
ACK_BOUND = 2.0  # seconds to wait at the end for reliable subscribers to acknowledge


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('bag_path', help='Bag to open.')
    parser.add_argument('-s', '--storage', default='', choices=STORAGES,
                        help='Storage implementation of bag. By default attempts to detect '
                        'automatically.')
    parser.add_argument('--topics', type=str, default=[], nargs='+',
                        help='Space-delimited list of topics to play.')
    parser.add_argument('--services', type=str, default=[], nargs='+',
                        help='Space-delimited list of services to play.')
    parser.add_argument('-r', '--rate', type=float, default=1.0,
                        help='rate at which to play back messages. Valid range > 0.0.')
    parser.add_argument('-l', '--loop', action='store_true',
                        help='enables loop playback when playing a bagfile: it starts back at '
                        'the beginning on reaching the end and plays indefinitely.')
    parser.add_argument('-m', '--remap', '--remappings', type=str, default=[], nargs='+',
                        help="list of topics to be remapped: in the form "
                        "'old_topic1:=new_topic1 old_topic2:=new_topic2 etc.'")
    parser.add_argument('-d', '--delay', type=float, default=0.0,
                        help='Sleep duration before play (each loop), in seconds. Negative '
                        'durations invalid.')
    parser.add_argument('--start-offset', type=float, default=0.0,
                        help='Start the playback player this many seconds into the bag file.')
    parser.add_argument('--start-paused', action='store_true',
                        help='Start the playback player in a paused state.')
    parser.add_argument('--disable-keyboard-controls', action='store_true',
                        help='disables keyboard controls for playback')
    parser.add_argument('--publish-service-requests', action='store_true',
                        help='Publish recorded service requests instead of recorded service '
                        'events')
    parser.add_argument('--service-requests-source', default='service_introspection',
                        choices=['service_introspection', 'client_introspection'],
                        help='Determine the source of the service requests to be replayed.')
    parser.set_defaults(_main=main)


def _validate(args: argparse.Namespace) -> str | None:
    if not args.rate > 0.0:
        return f'--rate must be greater than 0.0, got {args.rate:g}'
    if args.delay < 0.0:
        return f'--delay must be 0 or positive, got {args.delay:g}'
    if args.start_offset < 0.0:
        return f'--start-offset must be 0 or positive, got {args.start_offset:g}'
    for pair in args.remap:
        old, sep, new = pair.partition(':=')
        if not sep or not old or not new:
            return f"--remap: '{pair}' is not old_topic:=new_topic"
    return None


def main(args: argparse.Namespace) -> int | str:
    error = _validate(args)
    if error:
        return f'[ERROR] [ros2bag]: {error}'
    try:
        reader = BagReader(args.bag_path)
    except BagError as failure:
        return f'[ERROR] [ros2bag]: {failure}'
    try:
        with ros_node('rosbag2_player') as (node, stop):
            return Player(node, reader, args).run(stop)
    finally:
        reader.close()


def _absolute(name: str) -> str:
    return name if name.startswith('/') else '/' + name


class Player:
    """The rosbag2_player node: publishers (or service clients) fed at the recorded pace."""

    def __init__(self, node: Any, reader: BagReader, args: argparse.Namespace):
        self.node = node
        self.log = node.get_logger()
        self.reader = reader
        self.args = args
        self.paused = args.start_paused
        self.resumed = threading.Event()
        self.pause_started = time.monotonic()
        if not self.paused:
            self.resumed.set()
        self.paused_total = 0.0
        self.keys = SpaceKey(self.toggle_paused)
        remaps = dict(p.split(':=', 1) for p in args.remap)
        self.remaps = {_absolute(k): _absolute(v) for k, v in remaps.items()}
        self.publishers: dict[str, Any] = {}
        self.clients: dict[str, tuple[Any, Any]] = {}
        self.warned: set[str] = set()
        self.pending: list[Any] = []  # service requests sent, answers not yet seen

    # ---- pause ----
    def toggle_paused(self) -> None:
        if self.paused:
            self.paused = False
            self.paused_total += time.monotonic() - self.pause_started
            self.log.info('Resuming play.')
            self.resumed.set()
        else:
            self.paused = True
            self.pause_started = time.monotonic()
            self.resumed.clear()
            self.log.info('Pausing play.')

    # ---- endpoints ----
    def _selected(self) -> set[str]:
        topics = {_absolute(t) for t in self.args.topics}
        events = {_absolute(s) + '/_service_event' for s in self.args.services}
        return {t.name for t in self.reader.meta.topics
                if not (topics or events) or t.name in topics or t.name in events}

    def _create_endpoints(self, selected: set[str]) -> None:
        for topic in self.reader.meta.topics:
            if topic.name not in selected:
                continue
            is_event = is_service_event_topic(topic.name, topic.type)
            try:
                if is_event and self.args.publish_service_requests:
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
            self.publishers[topic.name] = self.node.create_publisher(
                msg_class, name, offer_qos_for_recorded(topic.offered_qos_profiles))

    def _wait_for_subscribers(self) -> None:
        """Until the graph is known and its subscribers have matched our endpoints (bounded).

        The `ros2` daemon's settled graph says how many subscribers each topic has: a fresh
        player may not have discovered them yet, and would otherwise play to nobody.
        """
        from ros2cli_lite.api import CliError
        from ros2cli_lite.graph import get_graph
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
    def run(self, stop: threading.Event) -> int | str:
        self.log.info(f'Set rate to {self.args.rate:g}')
        if not self.args.disable_keyboard_controls and self.keys.active:
            self.log.info('Adding keyboard callbacks.')
            self.log.info('Press SPACE for Pause/Resume')
            self.keys.start()
        try:
            self._create_endpoints(self._selected())
            self._wait_for_subscribers()
            self.log.info('Playback until timestamp: -1')
            while True:
                self._play_once(stop)
                if stop.is_set() or not self.args.loop:
                    break
            self._wait_for_acks()
        except BagError as error:
            return f'[ERROR] [ros2bag]: {error}'
        finally:
            self.keys.close()
        return 0

    def _sleep_until(self, target: float, stop: threading.Event) -> bool:
        """Wait for the wall-clock `target` (shifted by time spent paused); False on stop."""
        while not stop.is_set():
            if self.paused:
                self.resumed.wait(0.1)
                continue
            remaining = target + self.paused_total - time.monotonic()
            if remaining <= 0:
                return True
            stop.wait(min(remaining, 0.1))
        return False

    def _play_once(self, stop: threading.Event) -> None:
        meta = self.reader.meta
        offset_ns = int(self.args.start_offset * 1e9)
        first_stamp = meta.starting_time_ns + offset_ns
        self.paused_total = 0.0
        begin = time.monotonic() + self.args.delay
        if not self._sleep_until(begin, stop):
            return
        selected = set(self.publishers) | set(self.clients)
        for topic, stamp, data in self.reader.messages(selected, start_ns=first_stamp):
            target = begin + max(0, stamp - first_stamp) / 1e9 / self.args.rate
            if not self._sleep_until(target, stop):
                return
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
                  if self.args.service_requests_source == 'service_introspection'
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

        deadline = time.monotonic() + ACK_BOUND
        if self.pending:
            # Spinning takes the answers in: a request is only sure to have arrived then.
            from ros2cli_lite.node import spin_once
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
