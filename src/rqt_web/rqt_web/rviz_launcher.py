"""`rviz2 [-d FILE.rviz] [-f FRAME]`, `ros2 run rviz2 rviz2 ...`: open the RViz page.

Like the rqt commands: finds or starts the one web app of these ROS settings, prints the
page's URL and opens the default browser when there is one, then returns. The .rviz file is
read by the server when the page loads (upstream rviz2's YAML layout).
"""

from __future__ import annotations

import argparse
import os
import sys
import urllib.parse

from rqt_web import instance
from rqt_web.launcher import Announcer, _open_browser, _without_ros_args


def parse_args(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog='rviz2', description='Open RViz in the browser.')
    parser.add_argument('-d', '--display-config', metavar='FILE',
                        help='A display config file (.rviz) to load')
    parser.add_argument('-f', '--fixed-frame', metavar='FRAME',
                        help='Set the fixed frame')
    parser.add_argument('--no-browser', action='store_true',
                        help='only print the URL, do not open a browser')
    # rviz2's Qt and Ogre options the tutorials may type: accepted and ignored.
    parser.add_argument('-l', '--log', action='store_true', help=argparse.SUPPRESS)
    parser.add_argument('--splash-screen', help=argparse.SUPPRESS)
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    full_argv = sys.argv[1:] if argv is None else argv
    args = parse_args(_without_ros_args(full_argv))
    announcer = Announcer('rviz2', full_argv)
    query = {}
    if args.display_config:
        path = os.path.abspath(os.path.expanduser(args.display_config))
        if not os.path.isfile(path):
            print(f'rviz2: display config file {args.display_config} does not exist',
                  file=sys.stderr)
            return 1
        query['config'] = path
    if args.fixed_frame:
        query['fixed_frame'] = args.fixed_frame
    try:
        server, started = instance.ensure_running()
    except RuntimeError as error:
        print(f'rviz2: {error}', file=sys.stderr)
        return 1
    url = server.url('rviz') + ''.join(f'&{k}={urllib.parse.quote(v)}' for k, v in query.items())
    announcer.say(f'RViz: {url}' + ('' if started else ' (web app already running)'))
    if not args.no_browser:
        _open_browser(url, announcer.say)
    return 0


if __name__ == '__main__':
    sys.exit(main())
