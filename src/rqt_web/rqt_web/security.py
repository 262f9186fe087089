"""Who may talk to the server: the token in every URL, and Host/Origin checks.

- Token: `?token=` on a page URL (the launcher prints it), then a SameSite=Strict cookie set
  by that page for its scripts, API calls and WebSocket; `X-Rqt-Token` for programs.
- Host: only names of this machine (DNS rebinding: a foreign site's name resolving to
  127.0.0.1 still carries its own name in Host) unless the server listens on all interfaces.
- Origin / Sec-Fetch-Site: a request sent by another site's page is refused even when the
  browser would attach the cookie.
"""

from __future__ import annotations

import hmac
import secrets
from collections.abc import Awaitable, Callable

from aiohttp import web

LOCAL_NAMES = {'localhost', '127.0.0.1', '::1', '[::1]'}


def new_token() -> str:
    return secrets.token_hex(24)


def _host_name(host_header: str) -> str:
    if host_header.startswith('['):
        return host_header.split(']')[0] + ']'
    return host_header.rsplit(':', 1)[0] if host_header.count(':') == 1 else host_header


def cookie_name(port: int) -> str:
    # Cookies are per host, not per port: one name per server keeps two servers apart.
    return f'rqt_token_{port}'


def middleware(token: str, bind_host: str, port_holder: dict) -> Callable:
    """aiohttp middleware enforcing the rules above; refusals are 403 with one plain line."""
    allowed_hosts = LOCAL_NAMES | {bind_host}
    any_host = bind_host in ('0.0.0.0', '::', '')

    @web.middleware
    async def check(request: web.Request,
                    handler: Callable[[web.Request], Awaitable[web.StreamResponse]]
                    ) -> web.StreamResponse:
        host = request.headers.get('Host', '')
        if not any_host and _host_name(host) not in allowed_hosts:
            return _refuse(f'host {host!r} is not allowed (DNS rebinding protection)')
        origin = request.headers.get('Origin')
        if origin is not None and origin != f'{request.scheme}://{host}':
            return _refuse(f'cross-origin request from {origin!r} refused')
        if request.headers.get('Sec-Fetch-Site', 'same-origin') not in (
                'same-origin', 'none'):
            return _refuse('cross-site request refused')
        cookie = cookie_name(port_holder['port'])
        offered = (request.query.get('token') or request.headers.get('X-Rqt-Token')
                   or request.cookies.get(cookie) or '')
        if not hmac.compare_digest(offered.encode(), token.encode()):
            return _refuse('missing or wrong token: open the URL that rqt printed '
                           '(it ends with ?token=...)')
        response = await handler(request)
        if request.query.get('token') and request.method == 'GET' and not response.prepared:
            response.set_cookie(cookie, token, httponly=True, samesite='Strict', path='/')
        return response

    return check


def _refuse(reason: str) -> web.Response:
    return web.Response(status=403, text=f'403 Forbidden: {reason}\n')
