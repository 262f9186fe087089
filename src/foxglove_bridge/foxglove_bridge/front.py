"""One port for both subprotocols: read the WebSocket handshake, forward to the right server.

A client's upgrade request lists the subprotocols it speaks (`Sec-WebSocket-Protocol`).
Offered `foxglove.sdk.v1` (Foxglove's app) goes to the foxglove-sdk server, everything else
(`foxglove.websocket.v1`: Lichtblick, @foxglove/ws-protocol) to the v1 server; each answers
the handshake itself. Both listen on ephemeral loopback ports; this forwards bytes unchanged.
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


def offered_subprotocols(head: bytes) -> list[str]:
    value = headers(head).get('sec-websocket-protocol', '')
    return [p.strip() for p in value.split(',') if p.strip()]


def forbidden(reason: str) -> bytes:
    body = f'403 Forbidden: {reason}\n'.encode()
    return (b'HTTP/1.1 403 Forbidden\r\nContent-Type: text/plain; charset=utf-8\r\n'
            b'Content-Length: %d\r\nConnection: close\r\n\r\n' % len(body)) + body


async def _pipe(reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
    try:
        while data := await reader.read(CHUNK):
            writer.write(data)
            await writer.drain()
    except (ConnectionError, OSError):
        pass
    finally:
        with contextlib.suppress(Exception):
            writer.close()


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
        try:
            await asyncio.gather(_pipe(reader, up_writer), _pipe(up_reader, writer))
        except asyncio.CancelledError:
            # The bridge is stopping with this client connected: end quietly (asyncio would
            # print the cancelled connection task as a traceback).
            writer.close()
            up_writer.close()

    async def start(self, host: str, port: int) -> asyncio.Server:
        return await asyncio.start_server(self.handle, host, port, limit=HEAD_LIMIT,
                                          reuse_address=True)
