"""Hypothesis strategies and a long-lived target node for the fuzz tests (test_fuzz_*.py).

One node process serves a whole test module (start-up and discovery cost seconds); each
example calls it through clients created once, and checks what a user would see: an answer,
an ERROR line naming the field when refused, the process still running.
"""

from __future__ import annotations

import functools
import math
import os
import re
import struct
import time
from typing import Any

from hypothesis import HealthCheck, Phase, Verbosity, settings
from hypothesis import strategies as st
from rcl_interfaces.msg import ParameterType, ParameterValue

from ws_testing.support import RosProcess, TestNode

# Few examples in scripts/test (each is a real DDS round trip), a fixed derandomized sequence
# so CI runs are reproducible; bench/fuzz.py runs the same properties with 10,000 cases.
CI = settings(max_examples=int(os.environ.get('FUZZ_MAX_EXAMPLES', '40')), deadline=None,
              derandomize=not os.environ.get('FUZZ_RANDOM'),
              # No shrinking: after a crash every example fails slowly (timeouts); the first
              # failing example is reported as generated.
              phases=[Phase.explicit, Phase.reuse, Phase.generate],
              # bench/fuzz.py counts the cases from the verbose report.
              verbosity=Verbosity.verbose if os.environ.get('FUZZ_VERBOSE')
              else Verbosity.normal, database=None,
              suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow,
                                     HealthCheck.data_too_large])

FLOAT32_MAX = 3.4028234663852886e38
# Strings: ROS-name edge cases, the DDS length limit (247) and its surroundings, any unicode.
NAME_EDGES = ['', 'a', '_', '_a', 'a_', 'a__b', '1a', 'a/b', 'a//b', '/a', 'a/', '~', '~/a',
              '{node}', 'a b', 'é', 'turtle1', 'turtle1/x', 'ü' * 10, 'a' * 200, 'a' * 205,
              'a' * 210, 'a' * 211, 'a' * 212, 'a' * 247, 'a' * 248, 'a' * 300, 'a' * 1000,
              'rt/a', '\n', 'a' * 100 + '/' + 'b' * 100]
# Any unicode but NUL, which a ROS string cannot carry (the client library refuses it).
# (Lone surrogates are left out too: they have no UTF-8 form, the client refuses them.)
text = st.text(st.characters(codec='utf-8', exclude_characters='\x00'), max_size=1000)


def short(size: int) -> st.SearchStrategy[str]:
    """Like `text`, at most `size` characters (cheaper to generate than cutting `text`)."""
    return st.text(st.characters(codec='utf-8', exclude_characters='\x00'), max_size=size)


# Valid names twice as likely as arbitrary text, so the accepting paths get their share.
valid_names = st.from_regex(r'[A-Za-z][A-Za-z0-9]{0,30}(/[A-Za-z][A-Za-z0-9]{0,20}){0,3}',
                            fullmatch=True)
names = st.one_of(st.sampled_from(NAME_EDGES), valid_names, valid_names, text)
FLOAT_EDGES = [math.nan, math.inf, -math.inf, 0.0, -0.0, 5e-324, -5e-324, 1e-45, 1.1754943e-38,
               1e38, -1e38, FLOAT32_MAX, -FLOAT32_MAX, 1e308, -1e308]
floats64 = st.one_of(st.sampled_from(FLOAT_EDGES), st.floats(allow_nan=True, allow_infinity=True))
# What a float32 field can carry (rclpy rounds nothing: out-of-range values are refused on
# the client side already, so the server can only ever see these).
floats32 = st.one_of(st.sampled_from([f for f in FLOAT_EDGES if not math.isfinite(f)
                                      or abs(f) <= FLOAT32_MAX]),
                     st.floats(width=32, allow_nan=False, allow_infinity=False),
                     st.floats(-20.0, 20.0, width=32),
                     st.floats(width=32, allow_nan=True, allow_infinity=True))
uint8 = st.integers(0, 255)
int64 = st.integers(-2**63, 2**63 - 1)


def unknown_interface(name: str) -> bool:
    """Whether `name` ('pkg/msg/Type', 'pkg/Type', ...) names no interface importable here: for
    generated type names that must be refused."""
    import importlib
    parts = name.split('/')
    if len(parts) == 2:
        parts = [parts[0], 'msg', parts[1]]
    if len(parts) != 3 or parts[0] not in _interface_packages():
        return True
    try:
        return not hasattr(importlib.import_module(f'{parts[0]}.{parts[1]}'), parts[2])
    except ImportError:
        return True


@functools.cache
def _interface_packages() -> frozenset[str]:
    # From the ament index: importing each generated name would search all of sys.path.
    from ament_index_python import get_resources
    return frozenset(get_resources('rosidl_interfaces'))


def float32(value: float) -> float:
    return struct.unpack('f', struct.pack('f', value))[0]


def parameter_values() -> st.SearchStrategy[ParameterValue]:
    """Any ParameterValue, including a type byte that names no type and mismatched contents."""
    def build(kind: int, b: bool, i: int, d: float, s: str, n: int) -> ParameterValue:
        return ParameterValue(type=kind, bool_value=b, integer_value=i, double_value=d,
                              string_value=s, byte_array_value=[bytes([n % 256])] * (n % 3),
                              bool_array_value=[b] * (n % 3), integer_array_value=[i] * (n % 3),
                              double_array_value=[d] * (n % 3), string_array_value=[s] * (n % 3))
    kinds = st.one_of(st.integers(0, 9), st.integers(10, 255))
    return st.builds(build, kinds, st.booleans(), st.one_of(st.integers(-300, 300), int64),
                     floats64, text.map(lambda t: t[:50]), st.integers(0, 100))


def describe(value: ParameterValue) -> tuple[int, Any]:
    """(type, the value of that type) of a ParameterValue, to compare before and after."""
    field = {ParameterType.PARAMETER_BOOL: 'bool_value',
             ParameterType.PARAMETER_INTEGER: 'integer_value',
             ParameterType.PARAMETER_DOUBLE: 'double_value',
             ParameterType.PARAMETER_STRING: 'string_value'}.get(value.type)
    return value.type, getattr(value, field) if field else None


class Target:
    """A node process under fuzzing, a probe with clients made once, and log bookkeeping."""

    def __init__(self, process: RosProcess, probe: TestNode) -> None:
        self.process = process
        self.probe = probe
        self.clients: dict[str, Any] = {}
        self.mark = 0

    def client(self, srv_type: Any, name: str) -> Any:
        if name not in self.clients:
            client = self.probe.node.create_client(srv_type, name)
            if not client.wait_for_service(timeout_sec=20.0):
                raise AssertionError(f'{name} did not appear within 20 s')
            self.clients[name] = client
        return self.clients[name]

    def call(self, srv_type: Any, name: str, request: Any, timeout: float = 10.0) -> Any:
        """Call and return the response; fail when unanswered or when the node died."""
        self.mark = len(self.process.output)
        future = self.client(srv_type, name).call_async(request)
        self.probe.executor.spin_until_future_complete(future, timeout_sec=timeout)
        self.assert_alive()
        assert future.done(), f'{name} did not answer {request!r} within {timeout} s'
        return future.result()

    def new_output(self) -> str:
        return self.process.output[self.mark:]

    def wait_for_log(self, pattern: str, timeout: float = 5.0) -> re.Match[str]:
        deadline = time.monotonic() + timeout
        while True:
            match = re.search(pattern, self.new_output(), re.MULTILINE)
            if match:
                return match
            self.assert_alive()
            if time.monotonic() > deadline:
                raise AssertionError(f'{pattern!r} not logged; new output:\n{self.new_output()}')
            self.probe.spin_for(0.02)

    def assert_alive(self) -> None:
        assert self.process.popen.poll() is None, f'the node died:\n{self.process.output[-3000:]}'
        assert 'Traceback' not in self.process.output, self.process.output[-3000:]
