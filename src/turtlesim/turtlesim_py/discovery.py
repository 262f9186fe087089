"""Faster DDS discovery for our long-lived nodes: a participant that announces itself often.

Fast DDS announces each participant every 3 s once its first announcements are sent. A
process that missed those (it happens on localhost now and then) learns of the participant
only at the next one, and until both sides know each other a service request gets no reply.
`announce_often()`, called before rclpy.init, makes this process's participant announce
itself every 0.5 s (share/turtlesim/config/fastdds_announce.xml). A profile file the user
chose (FASTRTPS_/FASTDDS_DEFAULT_PROFILES_FILE) is left alone, and another RMW ignores it.
"""

from __future__ import annotations

import os
from pathlib import Path

PROFILE_VARIABLES = ('FASTRTPS_DEFAULT_PROFILES_FILE', 'FASTDDS_DEFAULT_PROFILES_FILE')


def profile_path() -> str | None:
    """The installed 0.5 s announcement profile, None when turtlesim's share has none."""
    from ament_index_python.packages import PackageNotFoundError, get_package_share_directory
    try:
        profile = Path(get_package_share_directory('turtlesim')) / 'config' / 'fastdds_announce.xml'
    except PackageNotFoundError:
        return None
    return str(profile) if profile.is_file() else None


def announce_often() -> None:
    """Point Fast DDS at the 0.5 s announcement profile unless a profile is already chosen."""
    if any(os.environ.get(name) for name in PROFILE_VARIABLES):
        return
    profile = profile_path()
    if profile is not None:
        os.environ['FASTRTPS_DEFAULT_PROFILES_FILE'] = profile
