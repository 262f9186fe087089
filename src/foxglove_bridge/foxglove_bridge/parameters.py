"""The bridge's ROS parameters (upstream's names and defaults, but address 127.0.0.1 here)."""

from __future__ import annotations

import re
from dataclasses import dataclass

from rcl_interfaces.msg import IntegerRange, ParameterDescriptor
from rclpy.node import Node

from foxglove_bridge.origin_policy import DEFAULT_ORIGINS, ORIGIN_PARAMETER

DEFAULT_CAPABILITIES = ['clientPublish', 'parameters', 'parametersSubscribe', 'services',
                        'connectionGraph', 'assets']
DEFAULT_ASSET_URI = (r'^package://(?:[-\w%]+/)*[-\w%.]+\.(?:dae|fbx|glb|gltf|jpeg|jpg|mtl|obj|png'
                     r'|stl|tif|tiff|urdf|webp|xacro)$')
INT_MAX = 2**31 - 1


@dataclass
class Settings:
    port: int
    address: str
    topic_whitelist: list[re.Pattern[str]]
    service_whitelist: list[re.Pattern[str]]
    param_whitelist: list[re.Pattern[str]]
    client_topic_whitelist: list[re.Pattern[str]]
    min_qos_depth: int
    max_qos_depth: int
    send_buffer_limit: int
    capabilities: list[str]
    asset_uri_allowlist: list[re.Pattern[str]]
    origin_allowlist: list[re.Pattern[str]]
    include_hidden: bool
    use_sim_time: bool


def _declare(node: Node, name: str, default: object, description: str,
             integer_range: tuple[int, int] | None = None) -> object:
    descriptor = ParameterDescriptor(name=name, description=description, read_only=True)
    if integer_range:
        descriptor.integer_range = [IntegerRange(from_value=integer_range[0],
                                                 to_value=integer_range[1], step=1)]
    return node.declare_parameter(name, default, descriptor).value


def _patterns(node: Node, name: str, values: list[str]) -> list[re.Pattern[str]]:
    patterns = []
    for value in values:
        try:
            patterns.append(re.compile(value))
        except re.error as error:
            node.get_logger().error(f"Ignoring invalid regular expression '{value}' in "
                                    f'{name}: {error}')
    return patterns


def declare_settings(node: Node) -> Settings:
    """Declare every parameter on `node` (read-only, as upstream) and return their values."""
    whitelist = {}
    for name, what in (('topic_whitelist', 'topic names'),
                       ('service_whitelist', 'service names'),
                       ('param_whitelist', 'parameter names'),
                       ('client_topic_whitelist', 'client-published topic names')):
        values = _declare(node, name, ['.*'],
                          f'List of regular expressions (ECMAScript) of whitelisted {what}.')
        whitelist[name] = _patterns(node, name, list(values))
    assets = _declare(node, 'asset_uri_allowlist', [DEFAULT_ASSET_URI],
                      'List of regular expressions (ECMAScript) of whitelisted asset URIs. '
                      'Uses the resource retriever to fetch assets.')
    origins = _declare(node, ORIGIN_PARAMETER, DEFAULT_ORIGINS,
                       'List of regular expressions (ECMAScript) of the web origins whose pages '
                       'may connect (whole-string match); clients sending no Origin header '
                       '(desktop apps, programs) always may.')
    return Settings(
        port=int(_declare(node, 'port', 8765, 'The TCP port to bind the WebSocket server to',
                          (0, 65535))),
        address=str(_declare(node, 'address', '127.0.0.1',
                             'The host address to bind the WebSocket server to')),
        min_qos_depth=int(_declare(node, 'min_qos_depth', 1, 'Minimum depth used for the QoS '
                                   'profile of subscriptions.', (0, INT_MAX))),
        max_qos_depth=int(_declare(node, 'max_qos_depth', 10, 'Maximum depth used for the QoS '
                                   'profile of subscriptions.', (0, INT_MAX))),
        send_buffer_limit=int(_declare(
            node, 'send_buffer_limit', 10000000, 'Connection send buffer limit in bytes. '
            "Messages will be dropped when a connection's send buffer reaches this limit to "
            'avoid a queue of outdated messages building up.', (0, 2**63 - 1))),
        capabilities=list(_declare(node, 'capabilities', DEFAULT_CAPABILITIES,
                                   'Server capabilities')),
        include_hidden=bool(_declare(node, 'include_hidden', False,
                                     'Include hidden topics and services')),
        asset_uri_allowlist=_patterns(node, 'asset_uri_allowlist', list(assets)),
        origin_allowlist=_patterns(node, ORIGIN_PARAMETER, list(origins)),
        use_sim_time=bool(node.get_parameter('use_sim_time').value),
        **whitelist,
    )


def allowed(patterns: list[re.Pattern[str]], name: str) -> bool:
    """Upstream matches the whole name against each expression."""
    return any(pattern.fullmatch(name) for pattern in patterns)
