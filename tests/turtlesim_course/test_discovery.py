"""node_runtime.discovery: the announcement profile and the participant-id rotation.

The rotation's effect over real DDS (a turtlesim restarted after SIGKILL gets its pen back
quickly) is measured by bench/soak.py and exercised by test_controller_lifecycle.py; here,
what each start is given.
"""

from __future__ import annotations

import os
import re
import tempfile
from pathlib import Path

import pytest
from node_runtime import discovery


@pytest.fixture
def clean_env(monkeypatch, tmp_path):
    for name in (*discovery.PROFILE_VARIABLES, discovery.DISCOVERY_SERVER_VARIABLE):
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setattr(tempfile, 'tempdir', str(tmp_path))
    monkeypatch.setenv('ROS_DOMAIN_ID', '7')
    monkeypatch.setenv('ROS_AUTOMATIC_DISCOVERY_RANGE', 'LOCALHOST')
    return monkeypatch


def started_profile(monkeypatch, fresh_port: bool = True) -> str:
    """The profile one process start is given."""
    for name in discovery.PROFILE_VARIABLES:
        monkeypatch.delenv(name, raising=False)
    discovery.announce_often(fresh_port)
    return os.environ['FASTRTPS_DEFAULT_PROFILES_FILE']


def participant_id(profile: str) -> int | None:
    found = re.search(r'<participantID>(\d+)</participantID>', Path(profile).read_text())
    return int(found.group(1)) if found else None


def test_consecutive_starts_get_different_participant_ids(clean_env):
    ids = [participant_id(started_profile(clean_env)) for _ in range(40)]
    assert ids == [i % discovery.LOCALHOST_IDS for i in range(40)]  # 0, 1, ... 31, 0, ...
    profile = started_profile(clean_env)
    assert discovery.is_ours(profile)
    assert '<nanosec>500000000</nanosec>' in Path(profile).read_text()  # still announces often


def test_rotation_stays_where_static_peers_reach_without_localhost(clean_env):
    clean_env.setenv('ROS_AUTOMATIC_DISCOVERY_RANGE', 'SUBNET')
    ids = [participant_id(started_profile(clean_env)) for _ in range(9)]
    assert ids == [0, 1, 2, 3, 0, 1, 2, 3, 0]


def test_each_domain_has_its_own_rotation(clean_env):
    first = participant_id(started_profile(clean_env))
    clean_env.setenv('ROS_DOMAIN_ID', '8')
    assert participant_id(started_profile(clean_env)) == first


def test_a_probe_keeps_the_plain_profile(clean_env):
    profile = started_profile(clean_env, fresh_port=False)
    assert profile == discovery.profile_path() and participant_id(profile) is None
    assert discovery.is_ours(profile)


def test_a_profile_the_user_chose_is_left_alone(clean_env, tmp_path):
    mine = tmp_path / 'mine.xml'
    mine.write_text('<profiles/>')
    clean_env.setenv('FASTDDS_DEFAULT_PROFILES_FILE', str(mine))
    discovery.announce_often()
    assert 'FASTRTPS_DEFAULT_PROFILES_FILE' not in os.environ
    assert not discovery.is_ours(str(mine))


def test_a_discovery_server_set_up_is_left_alone(clean_env):
    clean_env.setenv('ROS_DISCOVERY_SERVER', '127.0.0.1:11811')
    discovery.announce_often()
    assert 'FASTRTPS_DEFAULT_PROFILES_FILE' not in os.environ
