"""Faster DDS discovery for our long-lived nodes: announced often, and a fresh port per start.

Two Fast DDS behaviours slow down a node that (re)starts next to running ones:

- Fast DDS announces each participant every 3 s once its first announcements are sent. A
  process that missed those (it happens on localhost now and then) learns of the participant
  only at the next one, and until both sides know each other a service request gets no reply.
  Our profile (share/node_runtime/config/fastdds_announce.xml) announces every 0.5 s.
- A participant takes the lowest free participant id, so a process restarted after a SIGKILL
  gets the killed one's UDP ports back. Until the dead participant's lease ends (20 s), the
  running nodes' writers did not deliver to the new one: a restarted turtlesim answered
  turtle_controller's set_pen only 2.2-2.5 s after it was seen (0.01 s after a clean exit,
  or on another port). So each start takes the next participant id of a rotation kept per
  ROS_DOMAIN_ID, and Fast DDS moves on from it to the next free port.

`announce_often()`, called before rclpy.init, sets this up through FASTRTPS_DEFAULT_PROFILES_FILE.
A profile file the user chose (FASTRTPS_/FASTDDS_DEFAULT_PROFILES_FILE) is left alone, and
another RMW ignores it. So is a discovery-server set-up (ROS_DISCOVERY_SERVER): there the
server, not announcements to localhost ports, decides who meets whom (docs/discovery_server.md).
"""

from __future__ import annotations

import fcntl
import os
import tempfile
from pathlib import Path

PROFILE_VARIABLES = ('FASTRTPS_DEFAULT_PROFILES_FILE', 'FASTDDS_DEFAULT_PROFILES_FILE')
# Fast DDS turns a participant into a client of these servers when it reads this variable.
DISCOVERY_SERVER_VARIABLE = 'ROS_DISCOVERY_SERVER'
# rmw_fastrtps sends LOCALHOST discovery to participant ids 0-31 on 127.0.0.1, and Fast DDS
# sends to each ROS_STATIC_PEERS address (SUBNET, machines without multicast) at ids 0-3: a
# rotation inside that range keeps every start reachable by the others' announcements.
LOCALHOST_IDS = 32
OTHER_RANGE_IDS = 4


def profile_path() -> str | None:
    """The installed 0.5 s announcement profile, None when node_runtime's share has none."""
    from ament_index_python.packages import PackageNotFoundError, get_package_share_directory
    try:
        share = Path(get_package_share_directory('node_runtime'))
        profile = share / 'config' / 'fastdds_announce.xml'
    except PackageNotFoundError:
        return None
    return str(profile) if profile.is_file() else None


def _generated_dir() -> Path:
    return Path(tempfile.gettempdir()) / f'node_runtime-fastdds-{os.getuid()}'


def is_ours(profile: str | None) -> bool:
    """Whether a profiles-file setting was made by announce_often, not chosen by the user."""
    if not profile:
        return False
    return profile == profile_path() or Path(profile).parent == _generated_dir()


def announce_often(fresh_port: bool = True) -> None:
    """Point Fast DDS at our profile unless a profile or a discovery server is chosen.

    With `fresh_port` the profile also pins the next participant id of the rotation. Only for
    processes with a single ROS context: Fast DDS refuses a second participant with the same
    id in one process.
    """
    if any(os.environ.get(name) for name in (*PROFILE_VARIABLES, DISCOVERY_SERVER_VARIABLE)):
        return
    profile = profile_path()
    if profile is None:
        return
    if fresh_port:
        try:
            profile = _with_participant_id(profile, _next_participant_id())
        except OSError:
            pass  # an unwritable temporary directory: the plain profile still helps
    os.environ['FASTRTPS_DEFAULT_PROFILES_FILE'] = profile


def _next_participant_id() -> int:
    """Take the next id of this domain's rotation (shared by all of the user's processes)."""
    directory = _generated_dir()
    directory.mkdir(mode=0o700, exist_ok=True)
    if directory.stat().st_uid != os.getuid():
        raise PermissionError(f'{directory} belongs to another user')
    domain = os.environ.get('ROS_DOMAIN_ID', '').strip() or '0'
    counter = directory / f'next_participant_id.domain{domain}'
    with open(counter, 'a+') as handle:
        fcntl.flock(handle, fcntl.LOCK_EX)  # two processes starting together get two ids
        handle.seek(0)
        text = handle.read().strip()
        localhost = os.environ.get('ROS_AUTOMATIC_DISCOVERY_RANGE', '').strip() == 'LOCALHOST'
        rotation = LOCALHOST_IDS if localhost else OTHER_RANGE_IDS
        participant_id = int(text) % rotation if text.isdigit() else 0
        handle.seek(0)
        handle.truncate()
        handle.write(str((participant_id + 1) % rotation))
    return participant_id


def _with_participant_id(template: str, participant_id: int) -> str:
    """The profile with <participantID> set, written once per id next to the counter."""
    target = _generated_dir() / f'fastdds_announce_p{participant_id}.xml'
    text = Path(template).read_text().replace(
        '<rtps>', f'<rtps>\n      <participantID>{participant_id}</participantID>', 1)
    if not target.is_file() or target.read_text() != text:
        partial = target.with_suffix(f'.{os.getpid()}.tmp')
        partial.write_text(text)
        partial.replace(target)  # readers never see half a file
    return str(target)
