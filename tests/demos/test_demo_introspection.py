""""Configure service introspection" (Jazzy Demos), typed as the page says: introspection_service
and introspection_client of demo_nodes_cpp, their introspection set at run time with
`ros2 param set` (contents on the service, metadata on the client), then
`ros2 service echo --flow-style /add_two_ints` shows the four events of each call, the
contents only in the service's two."""
from __future__ import annotations

import re

from support import RosProcess, ros2

LOG = r'^\[INFO\] \[[\d.]+\] '


def events(echo: RosProcess) -> list[tuple[str, str, str]]:
    """(event_type, request, response) of each event echoed so far."""
    return re.findall(r'event_type: (\w+)\n(?:.*\n)*?request: (.*)\nresponse: (.*)\n---',
                      echo.output)


def test_the_pages_steps(ros_env, launch, tmp_path) -> None:
    service = launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'introspection_service'])
    client = launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'introspection_client'])
    client.wait_for_output(LOG + r'\[introspection_client\]: Result of add_two_ints: 5$',
                           timeout=30)
    service.wait_for_output(LOG + r'\[introspection_service\]: Incoming request\na: 2 b: 3$')

    def param_set(node: str, name: str, value: str) -> str:
        result = ros2(ros_env, 'param', 'set', node, name, value)
        return result.stdout + result.stderr  # ros2 param prints a refusal on stderr

    assert param_set('/introspection_service', 'service_configure_introspection',
                     'loud') == ("Setting parameter failed: must be one of 'disabled', "
                                 "'metadata', or 'contents'\n")
    assert param_set('/introspection_service', 'service_configure_introspection',
                     'contents') == 'Set parameter successful\n'
    assert param_set('/introspection_client', 'client_configure_introspection',
                     'metadata') == 'Set parameter successful\n'
    echo = launch(argv=['ros2', 'service', 'echo', '--flow-style', '/add_two_ints'])
    echo.wait_for_output(r'event_type: RESPONSE_RECEIVED(?:.*\n)*?'
                         r'.*event_type: RESPONSE_RECEIVED', timeout=20)
    seen = events(echo)
    assert ('REQUEST_SENT', '[]', '[]') in seen
    assert ('REQUEST_RECEIVED', '[{a: 2, b: 3}]', '[]') in seen
    assert ('RESPONSE_SENT', '[]', '[{sum: 5}]') in seen
    assert ('RESPONSE_RECEIVED', '[]', '[]') in seen
    assert {kind for kind, _request, _response in seen} == {
        'REQUEST_SENT', 'REQUEST_RECEIVED', 'RESPONSE_SENT', 'RESPONSE_RECEIVED'}
    assert re.search(r'client_gid: \[(\d+, ){15}\d+\]\n  sequence_number: \d+\n', echo.output)

    # The service's events stop when it is disabled again; the client's go on.
    assert param_set('/introspection_service', 'service_configure_introspection',
                     'disabled') == 'Set parameter successful\n'
    assert echo.stop() == 2  # ros2cli's exit code after Ctrl-C
    after = launch(argv=['ros2', 'service', 'echo', '--flow-style', '/add_two_ints'])
    after.wait_for_output(r'event_type: RESPONSE_RECEIVED(?:.*\n)*?'
                          r'.*event_type: RESPONSE_RECEIVED', timeout=20)
    assert {kind for kind, _request, _response in events(after)} == {
        'REQUEST_SENT', 'RESPONSE_RECEIVED'}
    assert after.stop() == 2
    for process in (client, service):
        assert process.stop() == 0


def test_demo_nodes_py_introspection(ros_env, launch) -> None:
    """demo_nodes_py's single-process variant, switched on at start-up with -p."""
    demo = launch(argv=['ros2', 'run', 'demo_nodes_py', 'introspection', '--ros-args', '-p',
                        'service_configure_introspection:=contents'])
    demo.wait_for_output(LOG + r'\[introspection_client\]: Result of add_two_ints: 5$',
                         timeout=30)
    echo = launch(argv=['ros2', 'service', 'echo', '/add_two_ints'])
    echo.wait_for_output(r'event_type: RESPONSE_SENT', timeout=20)
    assert {kind for kind, _request, _response in events(echo)} <= {
        'REQUEST_RECEIVED', 'RESPONSE_SENT'}
    assert echo.stop() == 2 and demo.stop() == 0
