"""get_ros_node(context): one rclpy node of the launch process, spun on a thread of its own
until the launch shuts down (what LifecycleNode subscribes and calls services with)."""

from __future__ import annotations

import os
import threading
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launch.launch_context import LaunchContext

_ATTRIBUTE = '_launch_ros_adapter'
_LOCK = threading.Lock()


class ROSAdapter:
    """An rclpy context, node and executor thread; stopped by shutdown()."""

    def __init__(self) -> None:
        import rclpy
        from rclpy.context import Context
        from rclpy.executors import SingleThreadedExecutor
        from rclpy.signals import SignalHandlerOptions
        self.context = Context()
        # The launch's asyncio loop owns Ctrl-C: rclpy must not install its handlers.
        rclpy.init(args=[], context=self.context,
                   signal_handler_options=SignalHandlerOptions.NO)
        self.ros_node = rclpy.create_node(f'launch_ros_{os.getpid()}', context=self.context)
        self._executor = SingleThreadedExecutor(context=self.context)
        self._executor.add_node(self.ros_node)
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._spin, daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        while not self._stop.is_set():
            self._executor.spin_once(timeout_sec=0.1)

    def shutdown(self) -> None:
        import rclpy
        self._stop.set()
        self._thread.join(timeout=2.0)
        self._executor.shutdown(timeout_sec=1.0)
        self.ros_node.destroy_node()
        rclpy.try_shutdown(context=self.context)


def get_ros_adapter(context: LaunchContext) -> ROSAdapter:
    """The launch's adapter, made on first use and shut down with the launch."""
    from launch.event_handlers import OnShutdown
    with _LOCK:
        adapter = getattr(context, _ATTRIBUTE, None)
        if adapter is None:
            adapter = ROSAdapter()
            setattr(context, _ATTRIBUTE, adapter)
            context.register_event_handler(OnShutdown(
                on_shutdown=lambda _event, _context: adapter.shutdown()))
    return adapter


def get_ros_node(context: LaunchContext) -> Any:
    return get_ros_adapter(context).ros_node
