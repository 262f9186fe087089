"""Buffer: tf2's BufferCore with waits, async lookups and the tf2_frames service."""
import threading
import time as wall
from collections.abc import Callable
from typing import Any

import rclpy.logging
from geometry_msgs.msg import TransformStamped
from rclpy.clock import Clock, JumpThreshold, TimeJump
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.task import Future
from tf2_msgs.srv import FrameGraph
from tf2_py import BufferCore
from tf2_py.buffer_core import nanoseconds
from tf2_ros.buffer_interface import NO_WAIT, BufferInterface


class Buffer(BufferCore, BufferInterface):
    """Stores known frames and answers lookups; fill it with a TransformListener.

    With `node`, it also offers the `tf2_frames` service (every frame as YAML), which
    view_frames calls.
    """

    def __init__(self, cache_time: Duration | None = None, node: Node | None = None) -> None:
        BufferCore.__init__(self, cache_time)
        BufferInterface.__init__(self)
        self._new_data_callbacks: list[Callable[[], None]] = []
        self._callbacks_lock = threading.RLock()
        self._new_data = threading.Condition()
        if node is not None:
            self.srv = node.create_service(FrameGraph, 'tf2_frames', self._get_frames)
            self.clock = node.get_clock()
        else:
            self.clock = Clock()
        # A jump back in time (a bag looping, sim time restarting) makes every cached sample
        # "from the future": clear, as upstream does.
        threshold = JumpThreshold(min_forward=None, min_backward=Duration(seconds=-1),
                                  on_clock_change=True)
        self.jump_handle = self.clock.create_jump_callback(
            threshold, post_callback=self.time_jump_callback)

    def _get_frames(self, request: FrameGraph.Request,
                    response: FrameGraph.Response) -> FrameGraph.Response:
        response.frame_yaml = self.all_frames_as_yaml()
        return response

    def time_jump_callback(self, time_jump: TimeJump) -> None:
        rclpy.logging.get_logger('tf2_buffer').warning(
            'Detected jump back in time. Clearing tf buffer.')
        self.clear()

    def set_transform(self, transform: TransformStamped, authority: str) -> None:
        super().set_transform(transform, authority)
        self._call_new_data_callbacks()

    def set_transform_static(self, transform: TransformStamped, authority: str) -> None:
        super().set_transform_static(transform, authority)
        self._call_new_data_callbacks()

    def _call_new_data_callbacks(self) -> None:
        with self._new_data:
            self._new_data.notify_all()
        if not self._new_data_callbacks:
            return
        with self._callbacks_lock:
            for callback in list(self._new_data_callbacks):
                callback()

    def _remove_callback(self, callback: Callable[[], None]) -> None:
        with self._callbacks_lock:
            if callback in self._new_data_callbacks:
                self._new_data_callbacks.remove(callback)

    # --- blocking API ---------------------------------------------------------------------
    def lookup_transform(self, target_frame: str, source_frame: str, time: Any,
                         timeout: Duration = NO_WAIT) -> TransformStamped:
        """The transform from source_frame to target_frame at `time` (0: latest), waiting up
        to `timeout` for it to become available."""
        self.can_transform(target_frame, source_frame, time, timeout)
        return self.lookup_transform_core(target_frame, source_frame, time)

    def lookup_transform_full(self, target_frame: str, target_time: Any, source_frame: str,
                              source_time: Any, fixed_frame: str,
                              timeout: Duration = NO_WAIT) -> TransformStamped:
        """source_frame at source_time into target_frame at target_time, through fixed_frame."""
        self.can_transform_full(target_frame, target_time, source_frame, source_time,
                                fixed_frame, timeout)
        return self.lookup_transform_full_core(target_frame, target_time, source_frame,
                                               source_time, fixed_frame)

    def can_transform(self, target_frame: str, source_frame: str, time: Any,
                      timeout: Duration = NO_WAIT,
                      return_debug_tuple: bool = False) -> bool | tuple[bool, str]:
        result = self._wait(lambda: self.can_transform_core(target_frame, source_frame, time),
                            timeout)
        return result if return_debug_tuple else result[0]

    def can_transform_full(self, target_frame: str, target_time: Any, source_frame: str,
                           source_time: Any, fixed_frame: str,
                           timeout: Duration = NO_WAIT,
                           return_debug_tuple: bool = False) -> bool | tuple[bool, str]:
        result = self._wait(lambda: self.can_transform_full_core(
            target_frame, target_time, source_frame, source_time, fixed_frame), timeout)
        return result if return_debug_tuple else result[0]

    def _wait(self, check: Callable[[], tuple[bool, str]], timeout: Any) -> tuple[bool, str]:
        """check() until it succeeds or `timeout` (wall time) passes; woken by new data
        rather than polled. The data must arrive on another thread (the listener's own
        spin thread, or a multi-threaded executor), as upstream."""
        deadline = wall.monotonic() + nanoseconds(timeout) / 1e9
        result = check()
        while not result[0]:
            left = deadline - wall.monotonic()
            if left <= 0:
                break
            with self._new_data:
                self._new_data.wait(min(left, 0.1))
            result = check()
        return result

    # --- asynchronous API -----------------------------------------------------------------
    async def lookup_transform_async(self, target_frame: str, source_frame: str,
                                     time: Any) -> TransformStamped:
        await self.wait_for_transform_async(target_frame, source_frame, time)
        return self.lookup_transform_core(target_frame, source_frame, time)

    async def lookup_transform_full_async(self, target_frame: str, target_time: Any,
                                          source_frame: str, source_time: Any,
                                          fixed_frame: str) -> TransformStamped:
        await self.wait_for_transform_full_async(target_frame, target_time, source_frame,
                                                 source_time, fixed_frame)
        return self.lookup_transform_full_core(target_frame, target_time, source_frame,
                                               source_time, fixed_frame)

    def wait_for_transform_async(self, target_frame: str, source_frame: str,
                                 time: Any) -> Future:
        """A future done with the transform as soon as it can be looked up."""
        return self._future_when(
            lambda: self.can_transform_core(target_frame, source_frame, time)[0],
            lambda: self.lookup_transform_core(target_frame, source_frame, time))

    def wait_for_transform_full_async(self, target_frame: str, target_time: Any,
                                      source_frame: str, source_time: Any,
                                      fixed_frame: str) -> Future:
        args = (target_frame, target_time, source_frame, source_time, fixed_frame)
        return self._future_when(lambda: self.can_transform_full_core(*args)[0],
                                 lambda: self.lookup_transform_full_core(*args))

    def _future_when(self, ready: Callable[[], bool],
                     lookup: Callable[[], TransformStamped]) -> Future:
        future = Future()
        if ready():
            future.set_result(lookup())
            return future

        def on_new_data() -> None:
            if future.done():
                return
            try:
                if ready():
                    future.set_result(lookup())
            except Exception as error:  # handed to the awaiting code
                future.set_exception(error)

        with self._callbacks_lock:
            self._new_data_callbacks.append(on_new_data)
        future.add_done_callback(lambda _: self._remove_callback(on_new_data))
        return future
