"""Which web pages may open a connection: the Origin allow-list and the Host check.

Browsers apply no same-origin rule to WebSockets: any page the learner opens may connect to
ws://localhost:8765 and would then drive the robot. The browser does say who asks, in the
upgrade request's `Origin` (the page's site) and `Host` (the name the page used to reach us):

- `Origin`, when present, must match one of `origin_allowlist` (whole-string match, as the
  other allow-lists). Desktop apps and programs send none and are let in.
- `Host` must be a loopback name or the bound address: a DNS-rebinding page reaches
  127.0.0.1 under its own name, which the browser puts in `Host`. Bound to every interface
  (`address:=0.0.0.0`), any IP address and this machine's names are accepted.
"""

from __future__ import annotations

import ipaddress
import re
import socket

ORIGIN_PARAMETER = 'origin_allowlist'
DEFAULT_ORIGINS = [
    r'^https?://(?:localhost|127(?:\.\d{1,3}){3}|\[::1\])(?::\d+)?$',  # pages on this machine
    r'^https://(?:app|studio)\.foxglove\.dev$',                         # hosted Foxglove
    r'^https://lichtblick-suite\.github\.io$',                          # hosted Lichtblick
]
LOOPBACK_NAMES = frozenset({'localhost', '127.0.0.1', '::1'})
WILDCARDS = frozenset({'', '0.0.0.0', '::'})


def headers(head: bytes) -> dict[str, str]:
    """The request head's header fields, names lower-cased; repeated ones joined with ', '
    (as HTTP combines them: a doubled Origin or Host then matches nothing and is refused)."""
    fields: dict[str, str] = {}
    for line in head.decode('latin-1').split('\r\n')[1:]:
        name, separator, value = line.partition(':')
        if separator:
            key = name.strip().lower()
            fields[key] = f'{fields[key]}, {value.strip()}' if key in fields else value.strip()
    return fields


def host_name(host: str) -> str:
    """'example:8765' -> 'example', '[::1]:8765' -> '::1' (lower case)."""
    host = host.strip().lower()
    if host.startswith('['):
        return host[1:].partition(']')[0]
    return host.rpartition(':')[0] if host.count(':') == 1 else host


def _is_address(name: str) -> bool:
    try:
        ipaddress.ip_address(name)
    except ValueError:
        return False
    return True


class OriginPolicy:
    def __init__(self, allowed_origins: list[re.Pattern[str]], address: str) -> None:
        self.allowed_origins = allowed_origins
        self.address = address.strip().lower()
        self.hosts = set(LOOPBACK_NAMES) | {host_name(self.address) or self.address}
        if self.address in WILDCARDS:
            machine = socket.gethostname().lower()
            self.hosts |= {machine, machine + '.local', socket.getfqdn().lower()}

    def refusal(self, head: bytes) -> str | None:
        """Why this upgrade request is refused (one line naming the parameter), or None."""
        fields = headers(head)
        host = fields.get('host')
        if host is not None:
            name = host_name(host)
            if name not in self.hosts and not (self.address in WILDCARDS and _is_address(name)):
                return (f"Host '{host}' is neither a loopback name nor the bound address "
                        f"{self.address} (DNS rebinding?): connect to ws://localhost:<port>, or "
                        "set the 'address' parameter to the address clients use")
        origin = fields.get('origin')
        if origin is not None and not any(p.fullmatch(origin) for p in self.allowed_origins):
            return (f"Origin '{origin}' is not allowed: add a regular expression matching it to "
                    f"the '{ORIGIN_PARAMETER}' parameter to let pages of that site connect")
        return None
