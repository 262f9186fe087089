"""TransformListener: fills a Buffer from /tf and /tf_static."""
import atexit
import threading

import rclpy
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from tf2_msgs.msg import TFMessage
from tf2_ros.buffer import Buffer

# Upstream's listener QoS: /tf volatile, /tf_static transient-local so that a listener that
# starts late still receives every static frame published before it.
DYNAMIC_LISTENER_QOS = QoSProfile(depth=100, durability=DurabilityPolicy.VOLATILE,
                                  history=HistoryPolicy.KEEP_LAST)
STATIC_LISTENER_QOS = QoSProfile(depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                                 history=HistoryPolicy.KEEP_LAST)


class TransformListener:
    """Subscribes to /tf and /tf_static and stores what arrives in `buffer`.

    By default the subscriptions are on `node` and run when its executor spins them.
    spin_thread=True puts them on a small node of their own (`transform_listener_impl_...`,
    as rclcpp's listener names it) spun on a dedicated thread: lookups with a timeout can
    then wait inside any callback of `node`, whatever executor spins it. (Upstream's Python
    listener adds `node` itself to a second executor instead, which rclpy does not support.)
    """

    def __init__(self, buffer: Buffer, node: Node, *, spin_thread: bool = False,
                 qos: QoSProfile | int | None = None,
                 static_qos: QoSProfile | int | None = None) -> None:
        self.buffer = buffer
        self.node = node
        self._stop = threading.Event()
        if spin_thread:
            # Without the process's arguments, as rclcpp's: launch's `__node:=` rename would
            # name it like `node` ("Publisher already registered for node name" in its log).
            self.node = rclpy.create_node(
                f'transform_listener_impl_{id(self):x}', context=node.context,
                start_parameter_services=False, use_global_arguments=False)
        # Reentrant, so that a callback of the node may wait for transforms while these
        # subscriptions run on another thread of a multi-threaded executor.
        self.group = ReentrantCallbackGroup()
        self.tf_sub = self.node.create_subscription(
            TFMessage, '/tf', self.callback, DYNAMIC_LISTENER_QOS if qos is None else qos,
            callback_group=self.group)
        self.tf_static_sub = self.node.create_subscription(
            TFMessage, '/tf_static', self.static_callback,
            STATIC_LISTENER_QOS if static_qos is None else static_qos,
            callback_group=self.group)
        if spin_thread:
            self.executor = SingleThreadedExecutor(context=node.context)
            self.executor.add_node(self.node)
            self.dedicated_listener_thread = threading.Thread(
                target=self._spin, daemon=True, name='tf2_listener')
            self.dedicated_listener_thread.start()
            # Only the flag at shutdown: rclpy runs shutdown callbacks holding the context's
            # lock, which the thread needs to finish, so a join there waited its whole 2 s
            # (10 s for a process with five listeners). The join comes at exit instead, before
            # the interpreter finalizes with the thread still in rclpy's C++ (std::terminate).
            node.context.on_shutdown(self._stop.set)
            atexit.register(self._stop_spinning)

    def _spin(self) -> None:
        """Spin in short slices, so that shutdown finds no rclpy call in progress."""
        while not self._stop.is_set() and self.node.context.ok():
            try:
                self.executor.spin_once(timeout_sec=0.1)
            except (ExternalShutdownException, RuntimeError):
                break  # the context was shut down while waiting

    def _stop_spinning(self) -> None:
        self._stop.set()
        thread = getattr(self, 'dedicated_listener_thread', None)
        if thread is not None and thread is not threading.current_thread():
            thread.join(timeout=2.0)

    def __del__(self) -> None:
        self._stop_spinning()

    def unregister(self) -> None:
        """Stop listening: destroy both subscriptions."""
        self.node.destroy_subscription(self.tf_sub)
        self.node.destroy_subscription(self.tf_static_sub)

    def callback(self, data: TFMessage) -> None:
        for transform in data.transforms:
            self.buffer.set_transform(transform, 'default_authority')

    def static_callback(self, data: TFMessage) -> None:
        for transform in data.transforms:
            self.buffer.set_transform_static(transform, 'default_authority')
