"""The rqt web server (aiohttp): pages, a JSON API and one WebSocket per page for live data.

Started detached by the launchers (rqt_web/launcher.py); `python -m rqt_web.server --help`.
This module makes the app and runs it; what it serves is in `static_files` (the pages,
/static/, /vendor/), `api` (the JSON API), `live_session` (the WebSocket), `tf_feed`
(/api/tf/...) and `rviz_api` (/api/rviz/...). `security` checks every request first.
"""

from __future__ import annotations

import argparse
import asyncio
import os
import sys
import threading
from pathlib import Path

from aiohttp import web
from node_runtime.discovery import announce_often
from node_runtime.spinning import SIGNAL_CHECK_PERIOD, stop_on_signals

from rqt_web import api, instance, live_session, rviz_api, security, static_files, tf_feed
from rqt_web.ros_bridge import RosBridge


def make_app(token: str, bind_host: str, port_holder: dict) -> web.Application:
    app = web.Application(middlewares=[security.middleware(token, bind_host, port_holder)],
                          client_max_size=1 << 20)
    app['graph_sessions'] = set()
    app['log_sessions'] = set()
    app['sessions'] = set()

    app.router.add_routes([
        web.get('/', static_files.page), web.get('/api/ping', api.ping),
        web.get('/api/graph', api.graph), web.get('/api/interface', api.interface),
        web.post('/api/service/call', api.call_service),
        web.post('/api/topic/publish', api.publish), web.get('/api/parameters', api.parameters),
        web.post('/api/parameters/set', api.set_parameter),
        web.get('/ws', live_session.websocket),
        web.get('/static/{name:.+}', static_files.static_file),
        web.get('/vendor/{name:.+}', static_files.vendor_file),
        web.get('/{page}', static_files.page)])
    tf_feed.add_routes(app)  # /api/tf/...: the TF Tree and RViz pages' data
    rviz_api.add_routes(app)  # /api/rviz/...: .rviz files, robot description, meshes

    async def start_ros(app: web.Application) -> None:
        bridge = RosBridge(asyncio.get_running_loop())
        app['bridge'] = bridge

        def graph_changed(snapshot: dict) -> None:
            for session in list(app['graph_sessions']):
                session.send({'op': 'graph', 'graph': snapshot})

        def logged(entry: dict) -> None:
            for session in list(app['log_sessions']):
                session.send({'op': 'log', 'entries': [entry]})
        bridge.on_graph = graph_changed
        bridge.on_log = logged
        app['monitor'] = asyncio.ensure_future(live_session.monitor_loop(app))

    async def stop_ros(app: web.Application) -> None:
        app['monitor'].cancel()
        app['bridge'].shutdown()

    app.on_startup.append(start_ros)
    app.on_cleanup.append(stop_ros)
    return app


def parse_args(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog='python -m rqt_web.server', description=__doc__)
    parser.add_argument('--host', default='127.0.0.1')
    parser.add_argument('--port', type=int, default=0)
    parser.add_argument('--state-file', default=None,
                        help='where to write pid, port and token (default: per ROS settings)')
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if args.host not in ('127.0.0.1', 'localhost', '::1'):
        print(f'WARNING: listening on {args.host}: other machines can reach this server; '
              'only the token protects it', file=sys.stderr, flush=True)
    # node_runtime's handlers (not asyncio's): Ctrl-C and SIGTERM set `stop` and give the
    # server its shutdown budget; a SIGTERM while it stops ends it at once.
    stop = threading.Event()
    stop_on_signals(stop)
    announce_often()  # without it, 1 node start in 6 reached the graph only after 2-3 s
    token = security.new_token()
    port_holder = {'port': args.port}
    app = make_app(token, args.host, port_holder)
    state_path = Path(args.state_file) if args.state_file else instance.state_file()
    asyncio.run(_serve(app, args.host, port_holder, token, state_path, stop))
    return 0


async def _serve(app: web.Application, host: str, port_holder: dict, token: str,
                 state_path: Path, stop: threading.Event) -> None:
    runner = web.AppRunner(app, handle_signals=False, access_log=None)
    await runner.setup()
    site = web.TCPSite(runner, host, port_holder['port'])
    await site.start()
    port_holder['port'] = runner.addresses[0][1]
    server = instance.Instance(os.getpid(), host, port_holder['port'], token)
    instance.write_state(state_path, server)
    print(f'rqt web app listening on {host}:{server.port} (pid {server.pid})', flush=True)
    try:
        # Polled: the handler runs on this thread, between two of the loop's bytecodes.
        while not stop.is_set():
            await asyncio.sleep(SIGNAL_CHECK_PERIOD)
    finally:
        if instance.read_state(state_path) == server:
            state_path.unlink(missing_ok=True)
        await runner.cleanup()


if __name__ == '__main__':
    sys.exit(main())
