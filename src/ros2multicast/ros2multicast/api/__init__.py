"""One UDP multicast datagram, sent and received on the loopback interface only.

Upstream's ros2multicast sends out of the default multicast interface (the network) and
joins the group on any interface. This workspace may send nothing beyond this machine, so
the socket sends out of loopback (IP_MULTICAST_IF 127.0.0.1) with TTL 0 by default (the
kernel's multicast loop delivers the datagram to local listeners and no router forwards it),
and the receiver joins the group on loopback. It still tests what the page wants to know:
whether this machine delivers multicast between two processes.
"""

from __future__ import annotations

import socket
import time

DEFAULT_GROUP = '225.0.0.1'
DEFAULT_PORT = 49150
LOOPBACK = '127.0.0.1'
DEFAULT_TTL = 0
MAX_TTL = 1  # a datagram with a larger TTL could be routed off this machine
MESSAGE = b'Hello World!'


def send(data: bytes, *, group: str = DEFAULT_GROUP, port: int = DEFAULT_PORT,
         ttl: int | None = None) -> None:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP) as sock:
        sock.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_IF, socket.inet_aton(LOOPBACK))
        sock.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL,
                        DEFAULT_TTL if ttl is None else ttl)
        sock.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_LOOP, 1)
        sock.sendto(data, (group, port))


def receive(*, group: str = DEFAULT_GROUP, port: int = DEFAULT_PORT,
            timeout: float | None = None) -> tuple[bytes, tuple[str, int]]:
    """The first datagram to the group on loopback; TimeoutError after `timeout` seconds."""
    membership = socket.inet_aton(group) + socket.inet_aton(LOOPBACK)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP) as sock:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEPORT, 1)
        sock.bind(('', port))
        sock.settimeout(timeout)
        sock.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
        try:
            return sock.recvfrom(4096)
        finally:
            sock.setsockopt(socket.IPPROTO_IP, socket.IP_DROP_MEMBERSHIP, membership)


def loopback_delivers(timeout: float = 1.0) -> bool:
    """Whether a datagram sent to the group on loopback reaches a listener (ros2 doctor).

    The listener takes a free port, so no other sender or receiver is disturbed.
    """
    membership = socket.inet_aton(DEFAULT_GROUP) + socket.inet_aton(LOOPBACK)
    deadline = time.monotonic() + timeout
    try:
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP) as sock:
            sock.bind((DEFAULT_GROUP, 0))
            sock.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
            token = b'ros2doctor %d' % time.monotonic_ns()
            send(token, port=sock.getsockname()[1])
            while (left := deadline - time.monotonic()) > 0:  # skip any other datagram
                sock.settimeout(left)
                if sock.recvfrom(4096)[0] == token:
                    return True
    except OSError:  # no loopback to join or send on, or the timeout
        return False
    return False
