"""The daemon process: `python -m ros2cli.daemon.server` (started by the client).

One hidden rclpy node keeps the DDS graph cache warm; a threaded Unix-socket server answers
each request from it (see protocol.py). The first answer waits until discovery has settled;
later ones read the live cache. One-shot verbs run here for the CLI, in the same participant
(verb_host.py). Exits when stopped, on SIGTERM/SIGINT, or after IDLE_EXIT seconds without a
request.

A CLI whose environment is not the daemon's (an overlay sourced after the daemon started)
is pointed at the daemon's worker for that environment: this program with `--worker`
(workers.py).
"""

from __future__ import annotations

import fcntl
import os
import signal
import socketserver
import sys
import threading
import time
from pathlib import Path
from typing import Any

from ros2cli.daemon import protocol, verb_host
from ros2cli.daemon.workers import Workers, exit_with_daemon

IDLE_EXIT = 2 * 60 * 60.0      # as ros2cli's daemon: two hours without a request
READY_BOUND = 15.0             # a request waits at most this long for the first settling
SNAPSHOT_REUSE = 0.05          # concurrent requests within 50 ms share one snapshot
HEALTH_PERIOD = 2.0            # how often the participant checks that it still sees itself
# Every Fast DDS participant re-announces itself every 3 s (its default announcement period)
# to all 32 localhost participant ports; a new participant's first announcements are now and
# then not heard (measured here: 0-3.3 s until an existing node was known). So a fresh daemon
# answers once it has met every participant bound on this host (participants.py: 0.1-0.8 s
# next to a turtlesim here), or else after one whole period: then it has heard everyone who
# announces.
FIRST_LISTEN = 3.3
SETTLE_WHEN_MET = 0.1  # the graph unchanged this long: the last endpoints have trickled in


class GraphCache:
    """The daemon's node, rebuilt when its participant is lost; snapshots built under a lock."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._ready = threading.Event()
        self._context: Any = None
        self._node: Any = None
        self._reused: dict[bool, tuple[float, dict[str, Any]]] = {}

    def start(self) -> None:
        """Create the node and let discovery settle before the first answer (as the CLI did)."""
        from ros2cli.node import discovery as cli
        name = f'_ros2cli_daemon_{os.environ.get("ROS_DOMAIN_ID", "0") or "0"}_{os.getpid()}'
        started = time.monotonic()
        context, node, met = cli.meet_graph(name, FIRST_LISTEN)
        met_after = time.monotonic() - started
        if met:
            cli.wait_for_graph(node, settle=SETTLE_WHEN_MET, bound=2.0, everyone_met=True)
        else:  # and until every node's endpoints have arrived
            cli.wait_for_graph(node, bound=2.0)
        print(f'ready {time.monotonic() - started:.3f} s after creating the participant: '
              f'{"every participant met" if met else "not every participant met"} after '
              f'{met_after:.3f} s', file=sys.stderr, flush=True)
        with self._lock:
            self._context, self._node = context, node
            self._reused.clear()
        self._ready.set()

    def stop(self) -> None:
        import rclpy
        with self._lock:
            if self._node is not None:
                self._node.destroy_node()
                rclpy.try_shutdown(context=self._context)
                self._node = None

    def _rebuild(self, why: str) -> None:
        print(f'rebuilding the participant: {why}', file=sys.stderr, flush=True)
        self._ready.clear()
        self.stop()
        self.start()

    def healthy(self) -> bool:
        """Whether the node still sees itself in the graph (a lost participant would not)."""
        with self._lock:
            if self._node is None:
                return True
            try:
                return (self._node.get_name(), self._node.get_namespace()) in \
                    self._node.get_node_names_and_namespaces()
            except Exception:
                return False

    def watch(self, stopping: threading.Event) -> None:
        """Rebuild the participant when it no longer sees itself (checked twice, to be sure)."""
        misses = 0
        while not stopping.wait(HEALTH_PERIOD):
            if not self._ready.is_set():
                continue
            misses = 0 if self.healthy() else misses + 1
            if misses >= 2:
                self._rebuild('the node no longer sees itself in the graph')
                misses = 0

    def _with_node(self, query: Any) -> Any:
        if not self._ready.wait(READY_BOUND):
            raise TimeoutError('discovery did not settle in time')
        with self._lock:
            return query(self._node)

    def snapshot(self, detail: bool) -> dict[str, Any]:
        from ros2cli.graph import snapshot

        def build(node: Any) -> dict[str, Any]:
            now = time.monotonic()
            reused = self._reused.get(detail)
            if reused is not None and now - reused[0] < SNAPSHOT_REUSE:
                return reused[1]
            data = snapshot(node, detail)
            self._reused[detail] = (time.monotonic(), data)
            return data
        return self._with_node(build)

    def endpoints(self, topic: str) -> tuple[list[str], list[str]]:
        from ros2cli.graph import endpoint_texts
        return self._with_node(lambda node: endpoint_texts(node, topic))

    def endpoint_records(self, topic: str) -> tuple[list[dict], list[dict]]:
        from ros2cli.graph import endpoint_records
        return self._with_node(lambda node: endpoint_records(node, topic))

    def context(self) -> Any:
        """The participant's context once discovery has settled, else None (not waited for:
        until then the CLI runs its verbs itself)."""
        with self._lock:
            return self._context if self._ready.is_set() else None


class _Handler(socketserver.StreamRequestHandler):
    server: DaemonServer

    def handle(self) -> None:
        self.connection.settimeout(5.0)
        try:
            line = self.rfile.readline(protocol.MAX_MESSAGE)
            request = protocol.decode(line)
            if request.get('op') == 'run':
                self.connection.settimeout(None)
                self.server.run_verb(request, self.connection, self.wfile)
                return
            reply = self.server.answer(request)
        except (protocol.ProtocolError, OSError) as error:
            reply = {'ok': False, 'error': f'bad request: {error}'}
        except Exception as error:  # answer with the reason rather than a dropped connection
            reply = {'ok': False, 'error': f'{type(error).__name__}: {error}'}
        reply['version'] = self.server.version
        self.connection.settimeout(30.0)
        try:
            self.wfile.write(protocol.encode(reply))
        except OSError:
            pass  # the client gave up


class DaemonServer(socketserver.ThreadingUnixStreamServer):
    daemon_threads = True
    request_queue_size = 64

    def __init__(self, path: Path, cache: GraphCache, is_worker: bool = False) -> None:
        self.version = protocol.version()
        self.cache = cache
        self.loaded = verb_host.LoadedCode()
        self.last_request = time.monotonic()
        self.path = path
        self.is_worker = is_worker
        self.environment = protocol.environment()
        self.workers = Workers(path)
        old_umask = os.umask(0o177)  # the socket is created 0600: only its user may connect
        try:
            super().__init__(str(path), _Handler)
        finally:
            os.umask(old_umask)
        os.chmod(path, 0o600)

    def answer(self, request: dict[str, Any]) -> dict[str, Any]:
        self.last_request = time.monotonic()
        op = request.get('op')
        if op == 'hello':
            return {'ok': True, 'pid': os.getpid(), 'settings': protocol.settings()}
        if op == 'stop':
            threading.Thread(target=self.shutdown, daemon=True).start()
            return {'ok': True}
        if request.get('version') != self.version:
            return {'ok': False, 'error': 'version'}
        if op == 'graph':
            return {'ok': True, 'graph': self.cache.snapshot(bool(request.get('detail')))}
        if op == 'endpoints':
            publishers, subscribers = self.cache.endpoints(str(request.get('topic', '')))
            return {'ok': True, 'publishers': publishers, 'subscribers': subscribers}
        if op == 'endpoint_records':
            publishers, subscribers = self.cache.endpoint_records(str(request.get('topic', '')))
            return {'ok': True, 'publishers': publishers, 'subscribers': subscribers}
        return {'ok': False, 'error': f'unknown request {op!r}'}

    def run_verb(self, request: dict[str, Any], connection: Any, output: Any) -> None:
        """Run a one-shot verb for the CLI (verb_host.py), streaming its output; or decline with
        one line (naming the worker of the CLI's environment when there is one to ask), and
        the CLI runs it itself."""
        self.last_request = time.monotonic()
        if request.get('environment') != self.environment:
            worker = None if self.is_worker else self.workers.for_cli(request)
            output.write(protocol.encode({'declined': 'environment',
                                          'worker': str(worker) if worker else None}))
            return
        context = self.cache.context()
        reason = ('version' if request.get('version') != self.version else
                  'not ready' if context is None else
                  'stale' if self.loaded.changed() else None)
        if reason is not None:
            output.write(protocol.encode({'declined': reason}))
            # Stale code: the next request starts a daemon (or worker) on the new code; a
            # worker of another version will not serve its environment again either.
            if reason == 'stale' or (reason == 'version' and self.is_worker):
                threading.Thread(target=self.shutdown, daemon=True).start()
            return
        sending = threading.Lock()
        cancelled = threading.Event()

        def send(kind: str, text: str) -> None:
            with sending:
                try:
                    output.write(protocol.encode({kind: text}))
                    output.flush()
                except OSError:
                    cancelled.set()

        def watch_cli() -> None:  # the CLI sends nothing more: end of stream means it left
            try:
                connection.recv(1)
            except OSError:
                pass
            cancelled.set()
        threading.Thread(target=watch_cli, daemon=True).start()
        code = verb_host.run(request, context, send, cancelled)
        self.loaded.changed()  # stamp what the verb loaded, to notice a later rebuild
        send('exit', str(code))


def _exit_when_idle(server: DaemonServer, stopping: threading.Event) -> None:
    while not stopping.wait(10.0):
        if time.monotonic() - server.last_request > IDLE_EXIT:
            server.shutdown()
            return


def main(argv: list[str] | None = None) -> int:
    is_worker = '--worker' in (sys.argv[1:] if argv is None else argv)
    path = protocol.socket_path()
    if is_worker:
        path = protocol.worker_path(path, protocol.environment())
    lock = open(protocol.lock_path(path), 'a')  # held (and locked) for the process's life
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        return 0  # another daemon serves these settings already
    # We hold the lock, so a socket file left here belongs to a dead daemon: replace it.
    try:
        path.unlink()
    except FileNotFoundError:
        pass
    # Announced every 0.5 s: a participant that starts next to the daemon meets it within
    # ~0.5 s instead of at Fast DDS's 3 s period (the others do not answer a newcomer at
    # once). The participant id is left to Fast DDS: the rotation is for nodes restarted after
    # a SIGKILL, and a pinned id would be refused to a second participant of this process.
    from node_runtime.discovery import announce_often
    announce_often(fresh_port=False)
    cache = GraphCache()
    server = DaemonServer(path, cache, is_worker)
    stopping = threading.Event()

    def on_signal(signum: int, frame: Any) -> None:
        threading.Thread(target=server.shutdown, daemon=True).start()
    signal.signal(signal.SIGTERM, on_signal)
    signal.signal(signal.SIGINT, on_signal)
    threading.Thread(target=cache.start, daemon=True).start()
    threading.Thread(target=cache.watch, args=(stopping,), daemon=True).start()
    threading.Thread(target=_exit_when_idle, args=(server, stopping), daemon=True).start()
    if is_worker:
        threading.Thread(target=exit_with_daemon, args=(server.shutdown,), daemon=True).start()
    print(f'{"worker" if is_worker else "daemon"} {os.getpid()} serving {path} '
          f'({protocol.settings()})', file=sys.stderr, flush=True)
    try:
        server.serve_forever(poll_interval=0.5)
    finally:
        stopping.set()
        try:  # still ours: no other daemon binds this path while we hold the lock
            path.unlink()
        except OSError:
            pass
        server.server_close()
        server.workers.stop()
        cache.stop()
    return 0


if __name__ == '__main__':
    sys.exit(main())
