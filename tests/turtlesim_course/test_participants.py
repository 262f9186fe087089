"""Who is on this host's domain (ros2cli/node/participants.py), counted against real processes."""

import time

from ros2cli.node.participants import bound_participants, everyone_met, heard_participants


def wait_for(predicate, timeout, what, probe=None):
    deadline = time.monotonic() + timeout
    while not predicate():
        assert time.monotonic() < deadline, f'timed out after {timeout} s waiting for {what}'
        if probe is not None:
            probe.spin_for(0.02)
        else:
            time.sleep(0.02)


def test_participants_bound_heard_and_gone(domain, probe, launch):
    # The probe alone: its own port pair, and itself heard.
    assert bound_participants(domain) == 1
    wait_for(lambda: everyone_met(probe.node) is True, 5, 'the probe to count itself', probe)

    turtlesim = launch('turtlesim', 'turtlesim_node', '--headless')
    turtlesim.wait_for_output(r'Spawning turtle \[turtle1\]', timeout=30)
    assert bound_participants(domain) == 2
    wait_for(lambda: everyone_met(probe.node) is True, 10, 'turtlesim to be met', probe)
    # Met means: both participants heard, and turtlesim's node known by name.
    heard, named = heard_participants(probe.node)
    assert (len(heard), named) == (2, True)
    assert 'turtlesim' in probe.node.get_node_names()

    turtlesim.stop()
    wait_for(lambda: bound_participants(domain) == 1, 10, "turtlesim's ports to be closed")
