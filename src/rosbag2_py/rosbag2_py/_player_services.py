"""The player node's services, as Jazzy's (`~/pause`, `~/resume`, `~/toggle_paused`,
`~/is_paused`, `~/get_rate`, `~/set_rate`, `~/play_next`, `~/seek`, `~/stop`; types of
rosbag2_interfaces), answered by a thread of their own while the bag plays."""

from __future__ import annotations

import threading
import time
from typing import Any

PLAY_NEXT_BOUND = 2.0  # seconds play_next waits for the playing loop to publish


class PlayerServices:
    def __init__(self, player: Any, stop: threading.Event) -> None:
        from rosbag2_interfaces import srv

        self.player = player
        self.stop = stop
        node = player.node
        handlers = {'pause': (srv.Pause, self._pause), 'resume': (srv.Resume, self._resume),
                    'toggle_paused': (srv.TogglePaused, self._toggle),
                    'is_paused': (srv.IsPaused, self._is_paused),
                    'get_rate': (srv.GetRate, self._get_rate),
                    'set_rate': (srv.SetRate, self._set_rate),
                    'play_next': (srv.PlayNext, self._play_next),
                    'seek': (srv.Seek, self._seek), 'stop': (srv.Stop, self._stop)}
        self.services = [node.create_service(kind, f'~/{name}', handler)
                         for name, (kind, handler) in handlers.items()]
        self._done = threading.Event()
        self._thread = threading.Thread(target=self._spin, name='player_services', daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        from ros2cli_lite.node import spin_once

        while not self._done.is_set():
            try:
                spin_once(self.player.node, 0.05)
            except Exception:  # the context went down under us: playing is over
                return

    def close(self) -> None:
        self._done.set()
        self._thread.join(timeout=5)
        for service in self.services:
            self.player.node.destroy_service(service)

    # ---- handlers ----
    def _pause(self, _request: Any, response: Any) -> Any:
        if self.player.clock.pause():
            self.player.log.info('Pausing play.')
        return response

    def _resume(self, _request: Any, response: Any) -> Any:
        if self.player.clock.resume():
            self.player.log.info('Resuming play.')
        return response

    def _toggle(self, _request: Any, response: Any) -> Any:
        self.player.toggle_paused()
        return response

    def _is_paused(self, _request: Any, response: Any) -> Any:
        response.paused = self.player.clock.paused
        return response

    def _get_rate(self, _request: Any, response: Any) -> Any:
        response.rate = self.player.clock.rate
        return response

    def _set_rate(self, request: Any, response: Any) -> Any:
        response.success = self.player.clock.set_rate(request.rate)
        return response

    def _play_next(self, _request: Any, response: Any) -> Any:
        """Publish the next message at once; only while paused (else success is False)."""
        player = self.player
        if not player.clock.paused:
            response.success = False
            return response
        player.next_played.clear()
        player.next_wanted.set()
        player.clock.wake()
        deadline = time.monotonic() + PLAY_NEXT_BOUND
        while not player.next_played and time.monotonic() < deadline \
                and not player.finished.is_set():
            time.sleep(0.005)
        player.next_wanted.clear()
        response.success = bool(player.next_played)
        return response

    def _seek(self, request: Any, response: Any) -> Any:
        """Go on from the first message at or after the time (before the bag: its start)."""
        stamp = request.time.sec * 1_000_000_000 + request.time.nanosec
        self.player.seek_to = max(stamp, self.player.reader.meta.starting_time_ns)
        self.player.clock.wake()
        response.success = True
        return response

    def _stop(self, _request: Any, response: Any) -> Any:
        self.stop.set()
        self.player.clock.wake()
        return response
