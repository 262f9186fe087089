"""Installation troubleshooting, "Enable multicast": `ros2 multicast receive` in one terminal,
`ros2 multicast send` in another, with ros2cli's lines; the datagram stays on loopback.

`ros2 doctor`'s hint when multicast is blocked is checked by test_cli_doctor's run in a
network namespace whose loopback is down; here, that the doctor's probe succeeds on this
machine's loopback (no hint).
"""

from __future__ import annotations

import re

from ws_testing import RosProcess, ros2


def test_receive_then_send_as_the_page(ros_env, tmp_path) -> None:
    # The upstream group and port: one datagram, then both commands exit.
    receiver = RosProcess(['ros2', 'multicast', 'receive'], ros_env, tmp_path / 'receive.log')
    try:
        receiver.wait_for_output(r'^Waiting for UDP multicast datagram\.\.\.$')
        sent = ros2(ros_env, 'multicast', 'send')
        assert (sent.returncode, sent.stdout) == (0, 'Sending one UDP multicast datagram...\n')
        assert receiver.wait(timeout=10) == 0
    finally:
        receiver.stop()
    assert re.fullmatch(r"Waiting for UDP multicast datagram\.\.\.\n"
                        r"Received from 127\.0\.0\.1:\d+: 'Hello World!'\n", receiver.output), \
        receiver.output


def test_receive_is_bounded_and_bad_input_is_one_line(ros_env) -> None:
    # A group nobody sends to: --timeout ends the wait with one line.
    quiet = ros2(ros_env, 'multicast', 'receive', '--group', '239.255.77.77', '--timeout', '0.3')
    assert (quiet.returncode, quiet.stdout, quiet.stderr) == (
        1, 'Waiting for UDP multicast datagram...\n',
        'No UDP multicast datagram received within 0.3 s\n')
    for args, message in [
            (('send', '--group', '10.1.2.3'),
             "argument --group: '10.1.2.3' is not an IPv4 multicast address"),
            (('send', '--ttl', '5'), 'argument --ttl: value must be 0 or 1')]:
        result = ros2(ros_env, 'multicast', *args)
        assert result.returncode == 2 and message in result.stderr, result.stderr
        assert 'Traceback' not in result.stderr


def test_the_doctors_probe_is_received_on_loopback() -> None:
    from ros2multicast.api import loopback_delivers
    assert loopback_delivers()
