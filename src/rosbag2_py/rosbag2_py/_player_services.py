"""The player node's services, as Jazzy's (`~/pause`, `~/resume`, `~/toggle_paused`,
`~/is_paused`, `~/get_rate`, `~/set_rate`, `~/play_next`, `~/burst`, `~/seek`, `~/play`,
`~/stop`; types of rosbag2_interfaces), answered by a thread of their own while the bag plays.

`~/play_next` and `~/burst` work while paused only: they ask the playing loop for messages
at once (Steps) and wait until it has published them. `~/play` starts a playback once the
previous one has stopped; `ros2 bag play` (like Jazzy's) ends with its playback, so there it
always finds one running and is refused, without touching it.
"""

from __future__ import annotations

import threading
from typing import Any

STEP_BOUND = 2.0  # seconds a step request waits for the playing loop without any progress


class Steps:
    """Messages the paused playing loop is asked to publish at once (-1: all that are left)."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self.left = 0
        self.count = 0
        self._progress = threading.Event()

    def request(self, number: int) -> None:
        with self._lock:
            self.left, self.count = (number if number > 0 else -1), 0
            self._progress.clear()

    def wanted(self) -> bool:
        return self.left != 0

    def published(self) -> None:
        """The playing loop published one message (whether or not one was asked for)."""
        with self._lock:
            if self.left == 0:
                return
            self.count += 1
            if self.left > 0:
                self.left -= 1
        self._progress.set()

    def wake(self) -> None:
        """Playback ended: a waiting request looks at `done()` at once."""
        self._progress.set()

    def wait(self, done: Any) -> int:
        """Until all asked for are published, or `done()` (playback over), or the loop made no
        progress for STEP_BOUND seconds (it stands at the end of the bag); how many were."""
        while self.wanted() and not done():
            if not self._progress.wait(STEP_BOUND):
                break
            self._progress.clear()
        with self._lock:
            self.left = 0
            return self.count


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
                    'play': (srv.Play, self._play),
                    'play_next': (srv.PlayNext, self._play_next),
                    'burst': (srv.Burst, self._burst),
                    'seek': (srv.Seek, self._seek), 'stop': (srv.Stop, self._stop)}
        self.services = [node.create_service(kind, f'~/{name}', handler)
                         for name, (kind, handler) in handlers.items()]
        self._done = threading.Event()
        self._thread = threading.Thread(target=self._spin, name='player_services', daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        from ros2cli.node.direct import spin_once

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
        if response.success:
            self.player.log.info(f'Set rate to {request.rate:g}')
        else:
            self.player.log.warn(f'Failed to set rate to invalid value {request.rate:g}')
        return response

    def _play(self, _request: Any, response: Any) -> Any:
        """Jazzy's answer while a playback runs (its handler first applies the request's
        playback_duration/until to the running playback: a default request ends it)."""
        self.player.log.warn('Trying to play() while in playback, dismissing request.')
        response.success = False
        return response

    def _step(self, number: int) -> int:
        player = self.player
        player.steps.request(number)
        player.clock.wake()
        return player.steps.wait(
            lambda: player.finished.is_set() or self.stop.is_set() or player.seek_to is not None)

    def _play_next(self, _request: Any, response: Any) -> Any:
        """Publish the next message at once; only while paused (else success is False)."""
        if not self.player.clock.paused:
            self.player.log.warn('Called play next, but not in paused state.')
            response.success = False
            return response
        self.player.log.debug('Playing next message.')
        response.success = self._step(1) == 1
        return response

    def _burst(self, request: Any, response: Any) -> Any:
        """Publish `num_messages` (0: all that are left) as fast as possible; while paused."""
        if not self.player.clock.paused:
            self.player.log.warn('Burst can only be used when in the paused state.')
            response.actually_burst = 0
            return response
        response.actually_burst = self._step(int(request.num_messages))
        self.player.log.info(f'Burst {response.actually_burst} messages.')
        return response

    def _seek(self, request: Any, response: Any) -> Any:
        """Go on from the first message at or after the time (before the bag: its start)."""
        stamp = request.time.sec * 1_000_000_000 + request.time.nanosec
        self.player.seek_to = max(stamp, self.player.reader.meta.starting_time_ns)
        self.player.clock.wake()
        response.success = True
        return response

    def _stop(self, _request: Any, response: Any) -> Any:
        self.player.log.info('Stopping playback.')
        self.stop.set()
        self.player.clock.wake()
        return response
