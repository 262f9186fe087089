"""LaunchIntrospector: the tree `ros2 launch --print` shows."""

from __future__ import annotations

from typing import Any

from launch.action import Action
from launch.launch_description import LaunchDescription
from launch.utilities import normalize_to_list_of_substitutions

_STEP = '    '


def _indent(lines: list[str]) -> list[str]:
    return [_STEP + line for line in lines]


def _tree(lines: list[str]) -> list[str]:
    """Turn indentation into ├── / └── / │ branches (upstream's drawing)."""
    result: list[str] = []
    previous_depth: int | None = None
    for old in lines:
        if not old.startswith(_STEP):
            continue
        depth = len(old) - len(old.lstrip())
        if previous_depth is not None and '└' in result[-1] and previous_depth <= depth:
            result[-1] = result[-1].replace('└', '├', 1)
        previous_depth = depth
        line = '│' + old[1:]
        result.append(line[:depth - 4] + '└── ' + line[depth:])
    if result and result[-1].startswith('│'):
        result[-1] = ' ' + result[-1][1:]
    return result


def format_substitutions(substitutions: Any) -> str:
    """Substitutions as `describe()` shows them, joined (upstream's name)."""
    return ' + '.join(sub.describe() for sub in normalize_to_list_of_substitutions(
        substitutions))


def _format_entities(entities: list[Any]) -> list[str]:
    lines: list[str] = []
    for entity in entities:
        if isinstance(entity, Action):
            lines.extend(_format_action(entity))
        else:
            lines.append(f"Unknown entity('{entity}')")
    return lines


def _format_action(action: Action) -> list[str]:
    from launch.actions import EmitEvent, ExecuteProcess, LogInfo, RegisterEventHandler
    if isinstance(action, LogInfo):
        return [f'LogInfo({format_substitutions(action.msg)})']
    if isinstance(action, EmitEvent):
        return [f"EmitEvent(event='{action.event.name}')"]
    if isinstance(action, ExecuteProcess):
        cwd = 'None' if action.cwd is None else f"'{format_substitutions(action.cwd)}'"
        env = 'None' if action.env is None else '{' + ', '.join(
            f'{format_substitutions(k)}: {format_substitutions(v)}' for k, v in action.env
        ) + '}'
        cmd = ', '.join(format_substitutions(part) for part in action.cmd)
        return [f'ExecuteProcess(cmd=[{cmd}], cwd={cwd}, env={env}, shell={action.shell})']
    if isinstance(action, RegisterEventHandler):
        text, entities = action.event_handler.describe()
        return [f"RegisterEventHandler('{action.event_handler}'):",
                *_indent([text, *_indent(_format_entities(list(entities)))])]
    return [f"Action('{action}')"]


class LaunchIntrospector:
    def format_launch_description(self, launch_description: LaunchDescription) -> str:
        lines = _tree(_indent(_format_entities(launch_description.entities)))
        return f'{launch_description}\n' + '\n'.join(lines)
