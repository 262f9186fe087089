"""One port for both subprotocols: read the WebSocket handshake, forward to the right server.

A client's upgrade request lists the subprotocols it speaks (`Sec-WebSocket-Protocol`).
Offered `foxglove.sdk.v1` (Foxglove's app) goes to the foxglove-sdk server, everything else
(`foxglove.websocket.v1`: Lichtblick, @foxglove/ws-protocol) to the v1 server; each answers
the handshake itself. Both listen on ephemeral loopback ports; this forwards bytes unchanged.
"""

from __future__ import annotations

import asyncio
import contextlib

HEAD_LIMIT = 16 * 1024  # bytes of HTTP request head we read before giving up
HEAD_TIMEOUT = 10.0     # seconds a client may take to send its handshake
CHUNK = 256 * 1024


def offered_subprotocols(head: bytes) -> list[str]:
    offered = []
    for line in head.decode('latin-1').split('\r\n')[1:]:
        name, _, value = line.partition(':')
        if name.strip().lower() == 'sec-websocket-protocol':
            offered += [p.strip() for p in value.split(',') if p.strip()]
    return offered


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
    def __init__(self, sdk_port: int | None, v1_port: int) -> None:
        self.sdk_port = sdk_port
        self.v1_port = v1_port
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
