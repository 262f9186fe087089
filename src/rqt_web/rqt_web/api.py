"""The rqt pages' JSON API: one request, one answer (live data goes over `live_session`).

- GET /api/ping: the server's pid and whether the browser libraries are installed (the
  launchers ask it to know the server is up and is theirs).
- GET /api/graph: the graph snapshot once (the Foxglove page; the Node Graph's comes over
  its WebSocket as the graph changes).
- GET /api/interface?type=&kind=msg|srv|action[&part=]: a type's fields for a form.
- POST /api/service/call {name, type, values, timeout}: the Service Caller.
- POST /api/topic/publish {topic, type, values}: the Topics page's publisher.
- GET /api/parameters?node=, POST /api/parameters/set {node, name, value}: Parameters.

Bad input and ROS-side failures are answered `{"error": "..."}` with one line the page shows
as it is, never a traceback.
"""

from __future__ import annotations

import os
import time

from aiohttp import web

from rqt_web import forms
from rqt_web.ros_bridge import RosBridge
from rqt_web.static_files import vendor_installed

SERVICE_TIMEOUT_MAX = 60.0


async def ping(request: web.Request) -> web.Response:
    return web.json_response({'ok': True, 'pid': os.getpid(), 'vendor': vendor_installed()})


async def graph(request: web.Request) -> web.Response:
    bridge: RosBridge = request.app['bridge']
    return web.json_response(await bridge.run(bridge.snapshot))


async def interface(request: web.Request) -> web.Response:
    name = request.query.get('type', '')
    kind = request.query.get('kind', 'msg')
    part = request.query.get('part', '')
    try:
        cls = forms.interface_class(name, kind)
        if kind == 'srv':
            cls = cls.Request if part != 'response' else cls.Response
        elif kind == 'action':
            cls = {'result': cls.Result, 'feedback': cls.Feedback}.get(part, cls.Goal)
        return web.json_response({'fields': forms.describe(cls)})
    except forms.FormError as error:
        return web.json_response({'error': str(error)})


async def _json_body(request: web.Request) -> dict:
    try:
        body = await request.json()
    except (ValueError, UnicodeDecodeError):
        raise forms.FormError('the request body is not JSON') from None
    if not isinstance(body, dict):
        raise forms.FormError('the request body must be a JSON object')
    return body


def _error(message: str) -> web.Response:
    return web.json_response({'error': message})


async def call_service(request: web.Request) -> web.Response:
    bridge: RosBridge = request.app['bridge']
    from rosidl_runtime_py import message_to_ordereddict
    try:
        body = await _json_body(request)
        name, srv_type = str(body.get('name', '')), str(body.get('type', ''))
        timeout = body.get('timeout', 5.0)
        if isinstance(timeout, bool) or not isinstance(timeout, (int, float)) \
                or not 0 < timeout <= SERVICE_TIMEOUT_MAX:
            raise forms.FormError(f'timeout must be a number of seconds in (0, '
                                  f'{SERVICE_TIMEOUT_MAX:g}], got {timeout!r}')
        srv_class = forms.interface_class(srv_type, 'srv')
        msg = forms.build(srv_class.Request, body.get('values'))
        started = time.monotonic()
        response = await bridge.call_service(name, srv_type, msg, float(timeout))
    except (forms.FormError, TimeoutError) as error:
        return _error(str(error))
    except Exception as error:  # e.g. rclpy refusing the service name
        return _error(f'call failed: {error}')
    return web.json_response({'response': message_to_ordereddict(response),
                              'seconds': round(time.monotonic() - started, 4)})


async def publish(request: web.Request) -> web.Response:
    bridge: RosBridge = request.app['bridge']
    try:
        body = await _json_body(request)
        topic, msg_type = str(body.get('topic', '')), str(body.get('type', ''))
        msg = forms.build(forms.interface_class(msg_type, 'msg'), body.get('values'))
        forms.check_topic_name(topic)
        await bridge.publish(topic, msg_type, msg)
    except forms.FormError as error:
        return _error(str(error))
    return web.json_response({'published': True})


def _check_node_name(name: str) -> None:
    """A fully qualified node name is a valid absolute name: its services are named under it."""
    from rclpy.validate_full_topic_name import validate_full_topic_name
    try:
        validate_full_topic_name(name, is_service=True)
    except Exception as error:  # rclpy's InvalidServiceNameException and friends
        raise forms.FormError(f'invalid node name {name!r}: {error}') from None


async def _parameter_infos(bridge: RosBridge, node: str, names: list[str] | None = None
                           ) -> list[dict]:
    from rcl_interfaces.srv import DescribeParameters, GetParameters, ListParameters

    _check_node_name(node)
    if names is None:
        listed = await bridge.call_service(f'{node}/list_parameters',
                                           'rcl_interfaces/srv/ListParameters',
                                           ListParameters.Request(), 5.0)
        names = sorted(listed.result.names)
    described = await bridge.call_service(f'{node}/describe_parameters',
                                          'rcl_interfaces/srv/DescribeParameters',
                                          DescribeParameters.Request(names=names), 5.0)
    values = await bridge.call_service(f'{node}/get_parameters',
                                       'rcl_interfaces/srv/GetParameters',
                                       GetParameters.Request(names=names), 5.0)
    return [forms.describe_parameter(d, v)
            for d, v in zip(described.descriptors, values.values, strict=False)]


async def parameters(request: web.Request) -> web.Response:
    node = request.query.get('node', '')
    try:
        infos = await _parameter_infos(request.app['bridge'], node)
    except forms.FormError as error:
        return _error(str(error))
    except TimeoutError as error:
        return _error(f'{node} offers no parameter services ({error})')
    return web.json_response({'node': node, 'parameters': infos})


async def set_parameter(request: web.Request) -> web.Response:
    from rcl_interfaces.msg import Parameter
    from rcl_interfaces.srv import SetParameters
    bridge: RosBridge = request.app['bridge']
    try:
        body = await _json_body(request)
        node, name = str(body.get('node', '')), str(body.get('name', ''))
        infos = await _parameter_infos(bridge, node, [name])
        if not infos or infos[0]['type'] == 'not set':
            raise forms.FormError(f"{node} has no parameter '{name}'")
        value = forms.parameter_value(infos[0], body.get('value'))
        answer = await bridge.call_service(
            f'{node}/set_parameters', 'rcl_interfaces/srv/SetParameters',
            SetParameters.Request(parameters=[Parameter(name=name, value=value)]), 5.0)
    except (forms.FormError, TimeoutError) as error:
        return _error(str(error))
    result = answer.results[0]
    if not result.successful:
        return _error(f'Setting parameter failed: {result.reason}')
    return web.json_response({'set': True})
