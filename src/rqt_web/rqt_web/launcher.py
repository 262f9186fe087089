"""`rqt`, `rqt_graph`, `ros2 run rqt_console rqt_console`, ...: open a page of the web app.

Each command finds (or starts, detached) the one rqt web server for this user and these ROS
settings, prints the page's URL and opens the default browser when there is one. It returns
at once: the server keeps running for the next command (`rqt --stop` ends it).
"""

from __future__ import annotations

import argparse
import os
import sys
import webbrowser
from collections.abc import Callable

from rqt_web import instance

ALIASES = {'service_caller': 'services', 'reconfigure': 'parameters', 'params': 'parameters',
           'topic': 'topics', 'action': 'actions', 'rqt_graph': 'graph',
           'RosTfTree': 'tf_tree'}


def parse_args(argv: list[str], page: str | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog=os.path.basename(sys.argv[0]) or 'rqt',
        description='Open rqt in the browser (one local web app per user and ROS settings).')
    if page is None:
        parser.add_argument('page', nargs='?', default='index',
                            help='page to open: ' + ', '.join(instance.PAGES))
    parser.add_argument('--host', default='127.0.0.1',
                        help='address a newly started server listens on (default 127.0.0.1; '
                        '0.0.0.0 exposes it to the network)')
    parser.add_argument('--port', type=int, default=0,
                        help='port of a newly started server (default: a free one)')
    parser.add_argument('--no-browser', action='store_true',
                        help='only print the URL, do not open a browser')
    parser.add_argument('--stop', action='store_true',
                        help='stop the web app of these ROS settings and exit')
    # rqt's own options the tutorials may type; accepted and ignored here.
    parser.add_argument('--force-discover', action='store_true', help=argparse.SUPPRESS)
    parser.add_argument('-s', '--standalone', metavar='PLUGIN', help=argparse.SUPPRESS)
    return parser.parse_args(argv)


def main(argv: list[str] | None = None, page: str | None = None) -> int:
    full_argv = sys.argv[1:] if argv is None else argv
    args = parse_args(_without_ros_args(full_argv), page)
    announcer = Announcer('rqt', full_argv, os.path.basename(sys.argv[0]) or 'rqt')
    if args.stop:
        print('rqt: stopped' if instance.stop() else 'rqt: no web app is running')
        return 0
    page = page or args.page
    if args.standalone:
        page = args.standalone.split('.')[-1].removeprefix('rqt_')
    page = ALIASES.get(page, page)
    if page not in instance.PAGES:
        print(f"rqt: unknown page '{page}' (pages: {', '.join(instance.PAGES)})",
              file=sys.stderr)
        return 2
    if args.host not in ('127.0.0.1', 'localhost', '::1'):
        print(f'rqt: WARNING: listening on {args.host} exposes the app (services, parameters) '
              'to other machines; anyone with the URL and its token can use it',
              file=sys.stderr)
    try:
        server, started = instance.ensure_running(args.host, args.port)
    except RuntimeError as error:
        print(f'rqt: {error}', file=sys.stderr)
        return 1
    if not started and (args.host != '127.0.0.1' or args.port) and (
            server.host != args.host or (args.port and server.port != args.port)):
        print(f'rqt: reusing the running web app on {server.host}:{server.port} '
              f'(stop it with `rqt --stop` to change --host/--port)')
    url = server.url(page)
    # The index page's title is "rqt" itself: "rqt: rqt: URL" would read as a stutter.
    label = '' if page == 'index' else f'{instance.PAGES[page][1]}: '
    announcer.say(f'{label}{url}' + ('' if started else ' (web app already running)'))
    if not args.no_browser:
        _open_browser(url, announcer.say)
    return 0


def _open_browser(url: str, say: Callable[[str], None] | None = None) -> None:
    """Open `url` in the default browser when one can show it; never fail without one."""
    say = say or Announcer('rqt', []).say
    has_display = bool(os.environ.get('DISPLAY') or os.environ.get('WAYLAND_DISPLAY'))
    # Without a display, Python's webbrowser falls back to text browsers (lynx, w3m) that
    # would take over this terminal: only $BROWSER chosen by the user is used then.
    if not (os.environ.get('BROWSER') or has_display):
        say('no display here: open the URL above in a browser '
            '(over SSH: ssh -L PORT:127.0.0.1:PORT this-host, then the same URL)')
        return
    try:
        if not webbrowser.open(url):
            say('no browser found: open the URL above yourself')
    except webbrowser.Error as error:
        say(f'could not open a browser ({error}): open the URL above yourself')


class Announcer:
    """Says a line as `PROG: text` on stdout, and also through the ROS logger at INFO when
    stdout is no terminal: `ros2 launch` keeps a launched node's stdout in its log file
    (output='log', the default) but shows its log lines, so a learner who started rviz2 or
    rqt from a launch file still learns the page's URL."""

    def __init__(self, prog: str, argv: list[str], logger_name: str | None = None) -> None:
        self.prog = prog
        self.logger_name = _remapped_node_name(argv) or logger_name or prog
        self.logger = None

    def say(self, text: str) -> None:
        print(f'{self.prog}: {text}', flush=True)
        if sys.stdout.isatty():
            return
        if self.logger is None:
            # Imported only here: a launcher in a terminal stays quick to start.
            from rclpy.logging import get_logger
            self.logger = get_logger(self.logger_name)
        self.logger.info(text)


def _remapped_node_name(argv: list[str]) -> str | None:
    """The node name given by `--ros-args -r __node:=NAME` (as launch_ros's Node passes it)."""
    for previous, arg in zip(['', *argv], argv, strict=False):
        if previous in ('-r', '--remap') and arg.startswith('__node:='):
            return arg.split(':=', 1)[1] or None
    return None


def _without_ros_args(argv: list[str]) -> list[str]:
    """Drop `--ros-args ... [--]` (without importing rclpy: the launcher must be quick)."""
    kept, inside = [], False
    for arg in argv:
        if arg == '--ros-args':
            inside = True
        elif inside and arg == '--':
            inside = False
        elif not inside:
            kept.append(arg)
    return kept


def graph_main() -> int:
    return main(page='graph')


def console_main() -> int:
    return main(page='console')


if __name__ == '__main__':
    sys.exit(main())
