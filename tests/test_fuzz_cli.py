"""`ros2 service call`, `ros2 topic pub` and `ros2 param set` with generated YAML: never a
traceback, never a hang, and turtlesim stays up.

Each Hypothesis example is a batch of generated documents run as concurrent `ros2` processes
(a process costs most of a second to start; a batch keeps the budget small).
"""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor

import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from fuzz_support import CI, FLOAT_EDGES, text
from support import RosProcess, executable, leased_domain, ros2, ros_environment

FIELDS = ['r', 'g', 'b', 'width', 'off', 'x', 'y', 'theta', 'name', 'linear', 'angular', 'z',
          'data', '']
scalars = st.one_of(st.none(), st.booleans(), st.integers(-2**70, 2**70),
                    st.sampled_from(FLOAT_EDGES), st.floats(),
                    st.text(st.characters(codec='utf-8', exclude_characters='\x00'), max_size=30))
documents = st.recursive(
    scalars,
    lambda inner: st.one_of(st.lists(inner, max_size=4),
                            st.dictionaries(st.one_of(st.sampled_from(FIELDS), st.text(max_size=8)),
                                            inner, max_size=5)),
    max_leaves=12)


def as_yaml(document) -> str:
    try:
        return yaml.safe_dump(document, default_flow_style=True, allow_unicode=True).strip()
    except yaml.YAMLError:
        return str(document)


yaml_texts = st.one_of(documents.map(as_yaml), text.map(lambda t: t[:200]))
BATCH = st.lists(yaml_texts, min_size=6, max_size=6)
COMMANDS = {
    'service call': lambda doc: ['service', 'call', '/turtle1/set_pen', 'turtlesim/srv/SetPen',
                                 doc, '--timeout', '3'],
    'topic pub': lambda doc: ['topic', 'pub', '--once', '-w', '0', '--keep-alive', '0',
                              '/turtle1/cmd_vel', 'geometry_msgs/msg/Twist', doc],
    'param set': lambda doc: ['param', 'set', '/turtlesim', 'background_r', doc],
}


@pytest.fixture(scope='module')
def sim(tmp_path_factory):
    """One turtlesim for the module, and the environment to reach it."""
    tmp = tmp_path_factory.mktemp('fuzz-cli')
    with leased_domain() as domain:
        env = ros_environment(domain)
        process = RosProcess([executable('turtlesim', 'turtlesim_node'), '--headless'], env,
                             tmp / 'turtlesim.log')
        try:
            process.wait_for_output(r'Spawning turtle', timeout=20)
            yield process, env
        finally:
            assert process.stop() == 0, process.output[-3000:]
            assert 'Traceback' not in process.output, process.output[-3000:]


@pytest.mark.parametrize('verb', list(COMMANDS))
def test_cli_never_prints_a_traceback(verb, sim):
    process, env = sim

    @settings(CI, max_examples=1)
    @given(batch=BATCH)
    def check(batch):
        with ThreadPoolExecutor(max_workers=len(batch)) as pool:
            results = list(pool.map(
                lambda doc: (doc, ros2(env, *COMMANDS[verb](doc), timeout=30)), batch))
        for doc, result in results:
            output = result.stdout + result.stderr
            assert 'Traceback' not in output, (doc, output)
            assert result.returncode in (0, 1, 2), (doc, result.returncode, output)
            if result.returncode:
                assert result.stderr.strip(), (doc, 'refused without a word')
        assert process.popen.poll() is None, process.output

    check()
