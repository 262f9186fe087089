"""QoS on the command line (ros2topic.api's helpers): `--qos-*` options, the profile they
make, the profile compatible with a topic's publishers (which `topic echo` follows, see
adaptive_subscription.py), and ros2cli's incompatible-QoS warnings.

The warnings are rclpy's default event callbacks' lines. A verb run by the daemon would log to
the daemon's terminal, so there the same line goes to the verb's stderr (its context's),
which reaches the CLI.
"""

from __future__ import annotations

import argparse
import copy
import time
from collections.abc import Callable
from typing import Any

from ros2cli.verb_context import VerbContext

# rclpy 7.1's short keys (QoSPresetProfiles.short_keys(), ...), written out: the CLI builds
# its parser without importing rclpy (a verb the daemon runs never loads it); the test
# src/ros2topic/test/test_cli_qos.py checks them against rclpy's.
PROFILES = ['unknown', 'default', 'system_default', 'sensor_data', 'services_default',
            'parameters', 'parameter_events', 'action_status_default', 'best_available']
HISTORY = ['system_default', 'keep_last', 'keep_all', 'unknown']
RELIABILITY = ['system_default', 'reliable', 'best_effort', 'unknown', 'best_available']
DURABILITY = ['system_default', 'transient_local', 'volatile', 'unknown', 'best_available']
LIVELINESS = ['system_default', 'automatic', 'manual_by_topic', 'unknown', 'best_available']

POLICY_OPTIONS = ('qos_depth', 'qos_history', 'qos_reliability', 'qos_durability',
                  'qos_liveliness', 'qos_liveliness_lease_duration_seconds')


def add_qos_arguments(parser: argparse.ArgumentParser, subscribe_or_publish: str,
                      default_profile: str) -> None:
    """ros2topic's --qos-profile, --qos-depth, --qos-history, --qos-reliability,
    --qos-durability, --qos-liveliness, --qos-liveliness-lease-duration-seconds."""
    verb = subscribe_or_publish
    parser.add_argument(
        '--qos-profile', choices=PROFILES, default=default_profile,
        help=f'Quality of service preset profile to {verb} with (default: {default_profile})')
    history = 'keep_last'  # the history of 'default' and 'sensor_data', the verbs' presets
    parser.add_argument(
        '--qos-depth', metavar='N', type=int,
        help=f'Queue size setting to {verb} with (overrides depth value of --qos-profile '
        'option)')
    parser.add_argument(
        '--qos-history', choices=HISTORY,
        help=f'History of samples setting to {verb} with (overrides history value of '
        f'--qos-profile option, default: {history})')
    parser.add_argument(
        '--qos-reliability', choices=RELIABILITY,
        help=f'Quality of service reliability setting to {verb} with (overrides reliability '
        'value of --qos-profile option, default: Compatible profile with running endpoints )')
    parser.add_argument(
        '--qos-durability', choices=DURABILITY,
        help=f'Quality of service durability setting to {verb} with (overrides durability '
        'value of --qos-profile option, default: Compatible profile with running endpoints )')
    parser.add_argument(
        '--qos-liveliness', choices=LIVELINESS,
        help=f'Quality of service liveliness setting to {verb} with (overrides liveliness '
        'value of --qos-profile option')
    parser.add_argument(
        '--qos-liveliness-lease-duration-seconds', type=float,
        help=f'Quality of service liveliness lease duration setting to {verb} with '
        '(overrides liveliness lease duration value of --qos-profile option')


def policies_given(args: argparse.Namespace) -> bool:
    return any(getattr(args, name, None) is not None for name in POLICY_OPTIONS)


def qos_profile_from_args(args: argparse.Namespace) -> Any:
    """The --qos-profile preset with the policies given on the command line (a copy: rclpy's
    presets are shared objects)."""
    from rclpy.qos import QoSPresetProfiles

    profile = copy.copy(QoSPresetProfiles.get_from_short_key(args.qos_profile))
    return configure_profile(
        profile, reliability=args.qos_reliability, durability=args.qos_durability,
        depth=args.qos_depth, history=args.qos_history, liveliness=args.qos_liveliness,
        lease_seconds=args.qos_liveliness_lease_duration_seconds)


def configure_profile(profile: Any, *, reliability: str | None = None,
                      durability: str | None = None, depth: int | None = None,
                      history: str | None = None, liveliness: str | None = None,
                      lease_seconds: float | None = None) -> Any:
    """`profile` with the policies given by their short keys (None: keep the profile's); a
    transient-local profile of depth 0 gets depth 1, as ros2topic does. Returns `profile`."""
    from rclpy.duration import Duration
    from rclpy.qos import (
        QoSDurabilityPolicy,
        QoSHistoryPolicy,
        QoSLivelinessPolicy,
        QoSReliabilityPolicy,
    )

    if history:
        profile.history = QoSHistoryPolicy.get_from_short_key(history)
    if durability:
        profile.durability = QoSDurabilityPolicy.get_from_short_key(durability)
    if reliability:
        profile.reliability = QoSReliabilityPolicy.get_from_short_key(reliability)
    if liveliness:
        profile.liveliness = QoSLivelinessPolicy.get_from_short_key(liveliness)
    if lease_seconds is not None and lease_seconds >= 0:
        profile.liveliness_lease_duration = Duration(nanoseconds=int(lease_seconds * 1e9))
    if depth is not None and depth >= 0:
        profile.depth = depth
    elif profile.durability == QoSDurabilityPolicy.TRANSIENT_LOCAL and profile.depth == 0:
        profile.depth = 1
    return profile


def compatible_profile(profile: Any, infos: list[Any], say: Callable[[str], None]) -> Any:
    """`profile` with the reliability and durability that connect to every publisher of
    `infos` (unchanged without publishers); `say` gets ros2cli's notices of a fallback.
    Returns `profile`."""
    from rclpy.qos import QoSDurabilityPolicy, QoSReliabilityPolicy

    if not infos:
        return profile
    reliable = sum(i.qos_profile.reliability == QoSReliabilityPolicy.RELIABLE for i in infos)
    latched = sum(i.qos_profile.durability == QoSDurabilityPolicy.TRANSIENT_LOCAL
                  for i in infos)
    if reliable == len(infos):
        profile.reliability = QoSReliabilityPolicy.RELIABLE
    else:
        if reliable:
            say('Some, but not all, publishers are offering QoSReliabilityPolicy.RELIABLE. '
                'Falling back to QoSReliabilityPolicy.BEST_EFFORT as it will connect to all '
                'publishers')
        profile.reliability = QoSReliabilityPolicy.BEST_EFFORT
    if latched == len(infos):
        profile.durability = QoSDurabilityPolicy.TRANSIENT_LOCAL
    else:
        if latched:
            say('Some, but not all, publishers are offering '
                'QoSDurabilityPolicy.TRANSIENT_LOCAL. Falling back to '
                'QoSDurabilityPolicy.VOLATILE as it will connect to all publishers')
        profile.durability = QoSDurabilityPolicy.VOLATILE
    return profile


def _warn(node: Any, text: str, context: VerbContext) -> None:
    logger = node.get_logger()
    if not context.in_daemon:
        logger.warn(text)
    else:  # rclpy would log to the daemon's terminal: the same line goes to the CLI's stderr
        print(f'[WARN] [{time.time():.9f}] [{logger.name}]: {text}', file=context.stderr,
              flush=True)


def subscription_events(node: Any, topic: str, context: VerbContext,
                        superseded: Callable[[], bool] | None = None) -> Any:
    """rclpy's default incompatible-QoS warning of a subscription, seen by the CLI; not given
    when `superseded()` says the subscription is about to be replaced."""
    from rclpy.event_handler import SubscriptionEventCallbacks
    from rclpy.qos import qos_policy_name_from_kind

    def incompatible(event: Any) -> None:
        if superseded is not None and superseded():
            return
        _warn(node, f"New publisher discovered on topic '{topic}', offering incompatible QoS. "
              'No messages will be received from it. Last incompatible policy: '
              f'{qos_policy_name_from_kind(event.last_policy_kind)}', context)

    return SubscriptionEventCallbacks(incompatible_qos=incompatible)


def publisher_events(node: Any, topic: str, context: VerbContext) -> Any:
    """rclpy's default incompatible-QoS warning of a publisher, seen by the CLI."""
    from rclpy.event_handler import PublisherEventCallbacks
    from rclpy.qos import qos_policy_name_from_kind

    def incompatible(event: Any) -> None:
        _warn(node, f"New subscription discovered on topic '{topic}', requesting incompatible "
              'QoS. No messages will be sent to it. Last incompatible policy: '
              f'{qos_policy_name_from_kind(event.last_policy_kind)}', context)

    return PublisherEventCallbacks(incompatible_qos=incompatible)
