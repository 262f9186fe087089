"""The `ros2` command's packages keep upstream's shape, and a verb gets what it needs as an
argument: checked from the source, no process started.

Every command package has `command/<command>.py`, `api/__init__.py` (what other code may
import) and one module per verb under `verb/` with `add_arguments(parser)` and
`main(args, context)`. A verb module prints only to a stream it names (its context's), since
the daemon runs the same code for a CLI whose terminal is not the daemon's; and no CLI or
daemon code keeps thread-local state or replaces `sys.stdout`/`sys.stderr`.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parent.parent / 'src'
# package -> its command (the ament index resource `ros2cli.command/<command>`)
COMMANDS = {'ros2cli': 'daemon', 'ros2topic': 'topic', 'ros2service': 'service',
            'ros2node': 'node', 'ros2param': 'param', 'ros2action': 'action',
            'ros2interface': 'interface', 'ros2lifecycle': 'lifecycle', 'ros2run': 'run',
            'ros2pkg': 'pkg', 'ros2doctor': 'doctor', 'ros2bag': 'bag',
            'ros2multicast': 'multicast', 'ros2launch': 'launch'}
# Commands without verbs: `ros2 run <pkg> <exe>`, `ros2 doctor`, `ros2 launch`.
NO_VERBS = {'ros2run', 'ros2doctor', 'ros2launch'}


def _verb_modules(package: str) -> list[Path]:
    root = SRC / package / package / 'verb'
    return sorted(path for path in root.rglob('*.py') if path.name != '__init__.py')


def _tree(path: Path) -> ast.Module:
    return ast.parse(path.read_text(), filename=str(path))


@pytest.mark.parametrize('package', sorted(COMMANDS))
def test_each_command_package_has_its_command_its_api_and_one_module_per_verb(package):
    command = COMMANDS[package]
    base = SRC / package / package
    assert (base / 'command' / f'{command}.py').is_file()
    resource = (SRC / package / 'resource' / 'commands' / command).read_text().splitlines()
    assert resource[0] == f'{package}.command.{command}'
    if package == 'ros2launch':
        return  # stays as it was: `ros2 launch` has neither verbs nor an api package
    if package != 'ros2cli':  # ros2cli's public modules are its api (ros2cli.graph, ...)
        assert (base / 'api' / '__init__.py').is_file()
    if package in NO_VERBS:
        return
    verbs = _verb_modules(package)
    assert verbs, f'{package} has no verb modules'
    for path in verbs:
        functions = {node.name: node for node in _tree(path).body
                     if isinstance(node, ast.FunctionDef)}
        assert 'add_arguments' in functions, path
        main = functions.get('main')
        assert main is not None and [a.arg for a in main.args.args] == ['args', 'context'], (
            f'{path}: main(args, context)')


def _print_without_stream(path: Path) -> list[int]:
    return [node.lineno for node in ast.walk(_tree(path))
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
            and node.func.id == 'print' and not any(k.arg == 'file' for k in node.keywords)]


def test_verbs_print_to_the_stream_their_context_gives():
    # A bare print() in a verb the daemon runs would go to the daemon's log, not the CLI.
    found = [f'{path.relative_to(SRC)}:{line}'
             for package in sorted(COMMANDS)
             for path in [*_verb_modules(package),
                          *sorted((SRC / package / package / 'command').glob('*.py'))]
             for line in _print_without_stream(path)]
    assert found == []


def _hidden_state(path: Path, root: Path = SRC) -> list[str]:
    found = []
    for node in ast.walk(_tree(path)):
        if isinstance(node, ast.Attribute) and node.attr == 'local' \
                and isinstance(node.value, ast.Name) and node.value.id == 'threading':
            found.append(f'{path.relative_to(root)}:{node.lineno}: threading.local')
        targets = node.targets if isinstance(node, ast.Assign) else (
            [node.target] if isinstance(node, ast.AnnAssign | ast.AugAssign) else [])
        for target in targets:
            if isinstance(target, ast.Attribute) and target.attr in ('stdout', 'stderr') \
                    and isinstance(target.value, ast.Name) and target.value.id == 'sys':
                found.append(f'{path.relative_to(root)}:{node.lineno}: sys.{target.attr} =')
    return sorted(found)


def test_no_thread_local_state_and_no_replaced_standard_streams_in_the_cli_and_daemon():
    found = [problem for package in sorted(COMMANDS)
             for path in sorted((SRC / package / package).rglob('*.py'))
             for problem in _hidden_state(path)]
    assert found == []


def test_the_checks_see_a_bare_print_a_thread_local_and_a_stream_assignment(tmp_path):
    probe = tmp_path / 'probe.py'
    probe.write_text('import sys\nimport threading\n\n\ndef main(args, context):\n'
                     '    print("x")\n    print("y", file=context.stdout)\n'
                     '    state = threading.local()\n    sys.stdout = state\n')
    assert _print_without_stream(probe) == [6]
    assert _hidden_state(probe, tmp_path) == ['probe.py:8: threading.local',
                                              'probe.py:9: sys.stdout =']
