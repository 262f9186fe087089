"""Who is on this host's domain: the participants that exist against those a node has heard.

A fresh participant does not know when discovery is complete: with Fast DDS and localhost-only
discovery the others sometimes answer only at their next periodic announcement, up to 3 s
later. But on one host the answer can be counted. Every RTPS participant binds its unicast
ports by the RTPS rule: metatraffic 7400 + 250 * domain + 10 + 2 * id and user traffic one
above it, listed in /proc/net/udp. Every ROS node publishes /rosout and /parameter_events,
and an endpoint's GID begins with its participant's GUID prefix. When as many participants
were heard as hold port pairs, and all their nodes have names, everyone has been met.
"""

from __future__ import annotations

from typing import Any

PORT_BASE = 7400
DOMAIN_GAIN = 250
METATRAFFIC_UNICAST_OFFSET = 10
PARTICIPANT_GAIN = 2
MAX_PARTICIPANTS = 120  # ids above would reach into the next domain's ports
ENDPOINTS_EVERY_NODE_HAS = ('/rosout', '/parameter_events')
GUID_PREFIX_BYTES = 12  # of an endpoint's GID: the participant's part
UNKNOWN_NODE_NAME = '_NODE_NAME_UNKNOWN_'  # rmw_dds_common's, until the node is known
_UDP_TABLES = ('/proc/net/udp', '/proc/net/udp6')


def bound_participants(domain: int) -> int | None:
    """How many participants of `domain` hold their unicast port pair on this host (in this
    network namespace); None where /proc/net/udp cannot be read."""
    first = PORT_BASE + DOMAIN_GAIN * domain + METATRAFFIC_UNICAST_OFFSET
    ports: set[int] = set()
    readable = False
    for table in _UDP_TABLES:
        try:
            with open(table) as lines:
                next(lines, None)  # the header
                for line in lines:
                    local = line.split(None, 2)[1]  # "0100007F:FD90"
                    ports.add(int(local.rsplit(':', 1)[1], 16))
            readable = True
        except (OSError, IndexError, ValueError):
            continue
    if not readable:
        return None
    # Both ports of a pair: one stray socket on an even port (an ephemeral one, for domains
    # whose ports lie in that range) is not taken for a participant.
    return sum(1 for pid in range(MAX_PARTICIPANTS)
               if {first + PARTICIPANT_GAIN * pid, first + PARTICIPANT_GAIN * pid + 1} <= ports)


def heard_participants(node: Any) -> tuple[set[bytes], bool]:
    """(the participants `node` knows of, whether it knows all their nodes' names).

    Participants by the GUID prefixes (the first 12 bytes of an endpoint's GID) of the /rosout
    and /parameter_events publishers, which every rclpy and rclcpp node has unless told
    otherwise. An endpoint's node is named once its participant's `ros_discovery_info` sample
    has arrived, which comes after the endpoint itself.
    """
    heard: set[bytes] = set()
    named = True
    for topic in ENDPOINTS_EVERY_NODE_HAS:
        for info in node.get_publishers_info_by_topic(topic):
            heard.add(bytes(info.endpoint_gid[:GUID_PREFIX_BYTES]))
            named = named and info.node_name != UNKNOWN_NODE_NAME
    return heard, named


def everyone_met(node: Any) -> bool | None:
    """Whether `node` has heard every participant bound on this host (itself included) and
    knows their nodes' names; None where the participants cannot be counted."""
    expected = bound_participants(node.context.get_domain_id())
    if expected is None:
        return None
    heard, named = heard_participants(node)
    return named and len(heard) >= expected
