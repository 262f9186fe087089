"""The launch's own ROS node (`launch_ros_<pid>`), for actions that need ROS in the launch
process itself: ROSTimer's clock, SetUseSimTime. Made on first use, in an rclpy context of
its own, spun on a thread, and shut down with the launch."""

from __future__ import annotations

import os
import threading
from typing import Any

import rclpy
from launch.event_handlers import OnShutdown
from rclpy.executors import SingleThreadedExecutor

_KEY = 'ros_adapter'


class ROSAdapter:
    def __init__(self, *, argv: list[str] | None = None, autostart: bool = True) -> None:
        self.__argv = list(argv or [])
        self.__context: Any = None
        self.__node: Any = None
        self.__executor: Any = None
        self.__thread: threading.Thread | None = None
        self.__running = threading.Event()
        if autostart:
            self.start()

    def start(self) -> None:
        if self.__running.is_set():
            raise RuntimeError('Cannot start a ROS adapter that is already running')
        self.__context = rclpy.Context()
        rclpy.init(args=self.__argv, context=self.__context)
        self.__node = rclpy.create_node(f'launch_ros_{os.getpid()}', context=self.__context)
        self.__executor = SingleThreadedExecutor(context=self.__context)
        self.__executor.add_node(self.__node)
        self.__running.set()
        # A daemon thread: a launch that ends without a Shutdown event must not hang on it.
        self.__thread = threading.Thread(target=self._spin, name='launch_ros adapter',
                                         daemon=True)
        self.__thread.start()

    def _spin(self) -> None:
        while self.__running.is_set():
            self.__executor.spin_once(timeout_sec=0.1)

    def shutdown(self) -> None:
        if not self.__running.is_set():
            raise RuntimeError('Cannot shutdown a ROS adapter that is not running')
        self.__running.clear()
        if self.__thread is not None:
            self.__thread.join(timeout=5.0)
        self.__executor.shutdown(timeout_sec=1.0)
        self.__node.destroy_node()
        rclpy.try_shutdown(context=self.__context)

    @property
    def argv(self) -> list[str]:
        return self.__argv

    @property
    def ros_context(self) -> Any:
        return self.__context

    @property
    def ros_node(self) -> Any:
        return self.__node

    @property
    def ros_executor(self) -> Any:
        return self.__executor


def get_ros_adapter(context: Any) -> ROSAdapter:
    if not hasattr(context.locals, _KEY):
        adapter = ROSAdapter()
        extend = getattr(context, 'extend_globals', context.extend_locals)
        extend({_KEY: adapter})
        context.register_event_handler(OnShutdown(
            on_shutdown=lambda *_args, **_kwargs: adapter.shutdown()))
    return getattr(context.locals, _KEY)


def get_ros_node(context: Any) -> Any:
    return get_ros_adapter(context).ros_node
