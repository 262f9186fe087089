"""turtlesim_node: the simulator, in a window when a display exists, headless otherwise."""

from __future__ import annotations

import argparse
import os
import sys
import threading
import time

import rclpy
from node_runtime.spinning import ros_session
from rclpy.executors import ExternalShutdownException, ShutdownException, SingleThreadedExecutor
from rclpy.utilities import remove_ros_args

from turtlesim_py import display

DEFAULT_CANVAS_PNG = 'turtlesim_canvas.png'


def parse_args(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog='turtlesim_node', description=__doc__)
    parser.add_argument('--headless', action='store_true',
                        help='never open a window (default when no display is available)')
    parser.add_argument('--fixed-step', action='store_true',
                        help='advance exactly 0.016 s per tick and publish /clock')
    parser.add_argument('--canvas-png', default=None, metavar='PATH',
                        help='write the canvas PNG here at shutdown and on '
                             '/turtlesim/_save_canvas (default: no PNG at shutdown; the '
                             f'service writes {DEFAULT_CANVAS_PNG} in the current directory)')
    parser.add_argument('--service-introspection', choices=('off', 'metadata', 'contents'),
                        default='off', help='service introspection on every served service')
    parser.add_argument('--tick-stats', metavar='PATH',
                        help='at shutdown, write tick cost statistics (JSON) to PATH')
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv if argv is None else argv
    args = parse_args(remove_ros_args(argv)[1:])
    windowed = display.wants_window(args.headless)
    problem = None
    if windowed:
        # Qt aborts the whole process when its platform plugin fails: look before creating
        # the application, and carry on headless with one line saying why and the fix.
        # (Logged once the node exists, as one WARN line of the node.)
        problem = display.window_problem()
        windowed = problem is None
    if not windowed:
        os.environ['QT_QPA_PLATFORM'] = 'offscreen'
    if windowed:
        from PySide6.QtWidgets import QApplication
        app = QApplication([argv[0]])
    else:
        from PySide6.QtGui import QGuiApplication
        app = QGuiApplication([argv[0]])

    from turtlesim_py.frame import TurtleFrame

    # node_runtime's handlers: Ctrl-C and SIGTERM only set `stop`, which the main thread
    # notices within 0.1 s; the canvas is then saved and logged while the context is still
    # valid, and the process exits with 0 (or within the shutdown budget, whatever hangs).
    with ros_session(argv) as stop:
        node = TurtleFrame(canvas_png=args.canvas_png or DEFAULT_CANVAS_PNG,
                           fixed_step=args.fixed_step, introspection=args.service_introspection)
        if problem:
            node.get_logger().warning(f'No window: {problem}; running headless')
        executor = make_executor()
        executor.add_node(node)
        # ROS callbacks on a spinning thread, the tick on its own thread (TurtleFrame.start),
        # the main thread waits for a signal (headless) or runs Qt (window).
        spinner = threading.Thread(target=_spin_quietly, args=(executor, stop), name='ros-spin',
                                   daemon=True)
        spinner.start()
        node.start()
        try:
            if windowed:
                _run_window(app, node, spinner, stop)
            else:
                # Sleep, never stop.wait(): the signal handler runs on this same thread and
                # calls stop.set(), which takes the event's non-reentrant lock; landing while
                # wait() holds that lock, it would wait for itself forever. (A turtlesim once
                # hung on SIGTERM in a test run this way, as far as the evidence goes.)
                while not stop.is_set() and spinner.is_alive():
                    time.sleep(0.1)
        finally:
            node.stop()
            if args.canvas_png:  # only when asked: no file appears in the directory unasked
                try:
                    path = node.save_canvas()
                    node.get_logger().info(f'Canvas written to {path}')
                except OSError as error:
                    node.get_logger().error(f'Could not write the canvas: {error}')
            if args.tick_stats:
                node.write_tick_stats(args.tick_stats)
            executor.shutdown(timeout_sec=2.0)
            spinner.join(timeout=2.0)
            node.destroy_node()
    return 0


def make_executor():
    """SingleThreadedExecutor, or rclpy's EventsExecutor with TURTLESIM_EXECUTOR=events.

    The EventsExecutor passes every turtlesim test and answers set_pen faster (p50 0.29 vs
    0.34 ms), but its idle spin_once wake-ups cost more than they save: 6.4 % of a core
    against 5.2 % in the one-turtle demo, so it is not the default (docs/turtlesim.md)."""
    if os.environ.get('TURTLESIM_EXECUTOR') == 'events':
        from rclpy.experimental.events_executor import EventsExecutor
        return EventsExecutor()
    return SingleThreadedExecutor()


def _run_window(app, node, spinner, stop: threading.Event) -> None:
    """Qt owns the main thread and repaints the window when the simulation changed."""
    from PySide6.QtCore import QTimer

    from turtlesim_py.window import CanvasWindow

    window = CanvasWindow(node)
    window.show()
    timer = QTimer()

    def refresh() -> None:
        if stop.is_set() or not spinner.is_alive():
            app.quit()
        elif node.dirty:
            node.dirty = False
            window.update()

    timer.timeout.connect(refresh)
    timer.start(16)
    app.exec()


def _spin_quietly(executor, stop: threading.Event) -> None:
    try:
        if isinstance(executor, SingleThreadedExecutor):
            # Blocks until executor.shutdown() at the end of main(): no idle wake-ups (each
            # costs a Python wait-set rebuild).
            executor.spin()
        else:
            # The EventsExecutor's spin() keeps a core busy in rclpy 7.1.6; spin_once does not.
            while not stop.is_set() and rclpy.ok():
                executor.spin_once(timeout_sec=0.1)
    except (KeyboardInterrupt, ExternalShutdownException, ShutdownException):
        pass


if __name__ == '__main__':
    sys.exit(main())
