"""The recorder node's services and events, as Jazzy's (rosbag2_transport's RecorderImpl).

`~/pause`, `~/resume`, `~/is_paused`, `~/split_bagfile` and, in snapshot mode only,
`~/snapshot` (types of rosbag2_interfaces); a WriteSplitEvent on `events/write_split` each
time a storage file is closed (at a split, and at the end with no file opened). They are
answered by the recorder's own executor, between two messages, so a split or a snapshot never
interleaves with a write.
"""

from __future__ import annotations

from typing import Any

from rosbag2_py._metadata_io import BagError, one_line

ACK_BOUND = 1.0  # seconds the last write_split event may wait for its subscribers


class RecorderServices:
    def __init__(self, recorder: Any) -> None:
        from rosbag2_interfaces import msg, srv

        self.recorder = recorder
        node = recorder.node
        handlers = {'split_bagfile': (srv.SplitBagfile, self._split),
                    'pause': (srv.Pause, self._pause), 'resume': (srv.Resume, self._resume),
                    'is_paused': (srv.IsPaused, self._is_paused)}
        if recorder.snapshot is not None:
            handlers['snapshot'] = (srv.Snapshot, self._snapshot)
        self.services = [node.create_service(kind, f'~/{name}', handler)
                         for name, (kind, handler) in handlers.items()]
        self.event_class = msg.WriteSplitEvent
        self.events = node.create_publisher(msg.WriteSplitEvent, 'events/write_split', 1)
        recorder.writer.on_split = self._publish_split

    def close(self) -> None:
        node = self.recorder.node
        self.recorder.writer.on_split = None
        for service in self.services:
            node.destroy_service(service)
        # The closing split's event goes out as the process ends: give subscribers up to
        # ACK_BOUND to take it, or a destroyed writer drops it (seen under load).
        from rclpy.duration import Duration
        self.events.wait_for_all_acked(Duration(seconds=ACK_BOUND))
        node.destroy_publisher(self.events)

    def _publish_split(self, closed: str, opened: str) -> None:
        event = self.event_class(closed_file=closed, opened_file=opened,
                                 node_name=self.recorder.node.get_fully_qualified_name())
        try:
            self.events.publish(event)
        except Exception as error:  # as Jazzy: a failed event never stops the recording
            self.recorder.log.error("Failed to publish message on '/events/write_split' topic. "
                                    f'\nError: {one_line(error)}')

    # ---- handlers ----
    def _split(self, _request: Any, response: Any) -> Any:
        try:
            self.recorder.writer.split()
        except (BagError, OSError) as error:
            self.recorder.log.error(f'Failed to split the bag: {one_line(error)}')
        return response

    def _pause(self, _request: Any, response: Any) -> Any:
        self.recorder.pause()
        return response

    def _resume(self, _request: Any, response: Any) -> Any:
        self.recorder.resume()
        return response

    def _is_paused(self, _request: Any, response: Any) -> Any:
        response.paused = bool(self.recorder.paused)
        return response

    def _snapshot(self, _request: Any, response: Any) -> Any:
        response.success = self.recorder.take_snapshot()
        return response
