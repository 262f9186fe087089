"""joint_state_publisher_gui: joint_state_publisher with sliders in the browser.

The node is joint_state_publisher itself (same name, parameters, /joint_states); the sliders
are the Joint State Publisher page of the rqt web app, which publishes the chosen positions on
SLIDERS_TOPIC (a sensor_msgs/JointState) that this node takes like a `source_list` topic.
At start it prints the page's URL (and opens the browser when there is one), as rviz2 does.
"""

from __future__ import annotations

import signal
import sys
import threading

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.signals import SignalHandlerOptions
from sensor_msgs.msg import JointState

from joint_state_publisher.joint_state_publisher import JointStatePublisher

SLIDERS_TOPIC = '/joint_state_publisher_gui/sliders'


def open_page() -> None:
    from rqt_web.launcher import _open_browser

    from rqt_web import instance
    try:
        server, _started = instance.ensure_running()
    except RuntimeError as error:
        print(f'joint_state_publisher_gui: {error}', file=sys.stderr)
        return
    url = server.url('joint_state_publisher')
    print(f'joint_state_publisher_gui: Joint State Publisher: {url}', flush=True)
    _open_browser(url)


def main(args: list[str] | None = None) -> None:
    stop = threading.Event()
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    for signum in (signal.SIGINT, signal.SIGTERM):
        signal.signal(signum, lambda _signum, _frame: stop.set())
    argv = rclpy.utilities.remove_ros_args(args or sys.argv)[1:]
    executor = SingleThreadedExecutor()
    node = None
    try:
        node = JointStatePublisher(argv[0] if argv else None)
        node.create_subscription(JointState, SLIDERS_TOPIC, node.on_source, 10)
        executor.add_node(node)
        threading.Thread(target=open_page, daemon=True).start()
        while not stop.is_set() and rclpy.ok():
            executor.spin_once(timeout_sec=0.1)
    except ExternalShutdownException:
        pass
    finally:
        executor.shutdown(timeout_sec=1.0)
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
