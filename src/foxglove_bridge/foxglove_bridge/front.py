"""One port for both subprotocols: read the WebSocket handshake, forward to the right server.

A client's upgrade request lists the subprotocols it speaks (`Sec-WebSocket-Protocol`).
Offered `foxglove.sdk.v1` (Foxglove's app; Lichtblick 1.28 offers it beside the other) goes to
the foxglove-sdk server, everything else (only `foxglove.websocket.v1`: older Lichtblick,
@foxglove/ws-protocol) to the v1 server; each answers the handshake itself. Both listen on
ephemeral loopback ports; this forwards bytes unchanged.
A request from a page the origin policy refuses (origin_policy.py) gets HTTP 403 here and
never reaches either server.
"""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import Callable

from foxglove_bridge.origin_policy import OriginPolicy, headers

HEAD_LIMIT = 16 * 1024  # bytes of HTTP request head we read before giving up
HEAD_TIMEOUT = 10.0     # seconds a client may take to send its handshake
CHUNK = 256 * 1024
DRAIN_TIMEOUT = 5.0  # seconds a server may take to close after its client left


def offered_subprotocols(head: bytes) -> list[str]:
    value = headers(head).get('sec-websocket-protocol', '')
    return [p.strip() for p in value.split(',') if p.strip()]


def forbidden(reason: str) -> bytes:
    body = f'403 Forbidden: {reason}\n'.encode()
    return (b'HTTP/1.1 403 Forbidden\r\nContent-Type: text/plain; charset=utf-8\r\n'
            b'Content-Length: %d\r\nConnection: close\r\n\r\n' % len(body)) + body


async def _to_server(reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
    """Client to server, then half-close: the server reads the end and closes by itself.

    A full close while the server still had data in flight for us (a browser tab that fell
    behind on a camera stream, then closed) resets its socket, and the SDK's server then logs
    'Broken pipe' once per queued message: hundreds of lines for one closed tab.
    """
    try:
        while data := await reader.read(CHUNK):
            writer.write(data)
            await writer.drain()
    except (ConnectionError, OSError):
        pass
    finally:
        with contextlib.suppress(Exception):
            writer.write_eof()


async def _to_client(reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
    """Server to client; once the client is gone, what the server still sends is read and
    dropped until it closes (bounded), so it never writes into a reset connection."""
    try:
        while data := await reader.read(CHUNK):
            writer.write(data)
            await writer.drain()
    except (ConnectionError, OSError):
        with contextlib.suppress(ConnectionError, OSError, asyncio.TimeoutError):
            await asyncio.wait_for(_drop_until_closed(reader), DRAIN_TIMEOUT)
    finally:
        with contextlib.suppress(Exception):
            writer.close()


async def _drop_until_closed(reader: asyncio.StreamReader) -> None:
    while await reader.read(CHUNK):
        pass


class Front:
    def __init__(self, sdk_port: int | None, v1_port: int, policy: OriginPolicy,
                 warn: Callable[[str], None]) -> None:
        self.sdk_port = sdk_port
        self.v1_port = v1_port
        self.policy = policy
        self.warn = warn
        self.counts = {'foxglove.sdk.v1': 0, 'foxglove.websocket.v1': 0}

    def backend(self, offered: list[str]) -> int:
        if 'foxglove.sdk.v1' in offered and self.sdk_port:
            self.counts['foxglove.sdk.v1'] += 1
            return self.sdk_port
        self.counts['foxglove.websocket.v1'] += 1
        return self.v1_port

    async def handle(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        try:
            head = await asyncio.wait_for(reader.readuntil(b'\r\n\r\n'), HEAD_TIMEOUT)
        except (asyncio.TimeoutError, asyncio.IncompleteReadError, asyncio.LimitOverrunError,
                ConnectionError):
            writer.close()
            return
        refusal = self.policy.refusal(head)
        if refusal is not None:
            self.warn(f'Refused a WebSocket connection: {refusal}')
            with contextlib.suppress(ConnectionError):
                writer.write(forbidden(refusal))
                await writer.drain()
            writer.close()
            return
        try:
            up_reader, up_writer = await asyncio.open_connection(
                '127.0.0.1', self.backend(offered_subprotocols(head)), limit=CHUNK)
        except OSError:
            writer.close()
            return
        up_writer.write(head)
        to_client = asyncio.ensure_future(_to_client(up_reader, writer))
        try:
            await _to_server(reader, up_writer)
            # The client is gone or done: the server closes on the end of its stream.
            await asyncio.wait({to_client}, timeout=DRAIN_TIMEOUT)
        except asyncio.CancelledError:
            # The bridge is stopping with this client connected: end quietly (asyncio would
            # print the cancelled connection task as a traceback).
            pass
        finally:
            to_client.cancel()
            writer.close()
            up_writer.close()

    async def start(self, host: str, port: int) -> asyncio.Server:
        return await asyncio.start_server(self.handle, host, port, limit=HEAD_LIMIT,
                                          reuse_address=True)
