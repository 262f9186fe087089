"""ros2 interface show: Output the interface definition."""

from __future__ import annotations

import argparse
import os
import re
import sys

from ros2cli.verb_context import CliError, VerbContext

from ros2interface.api import KINDS

HELP = 'Output the interface definition'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    group = parser.add_mutually_exclusive_group()
    group.add_argument('--all-comments', action='store_true',
                       help='Show all comments, including for nested interface definitions')
    group.add_argument('--no-comments', action='store_true',
                       help='Show no comments or whitespace')
    parser.add_argument('type', help="Show an interface definition (e.g. "
                        "'example_interfaces/msg/String'); '-' reads it from stdin")


PRIMITIVES = {
    'bool', 'byte', 'char', 'float32', 'float64', 'int8', 'uint8', 'int16', 'uint16', 'int32',
    'uint32', 'int64', 'uint64', 'string', 'wstring',
}


CONSTANT = re.compile(r'^\s*\S+\s+[A-Za-z_]\w*\s*=')


LEGACY = {'Header': 'std_msgs/msg/Header', 'time': 'builtin_interfaces/msg/Time',
          'duration': 'builtin_interfaces/msg/Duration'}


def definition_path(identifier: str) -> str:
    parts = identifier.split('/')
    if len(parts) != 3:
        raise CliError(f"Invalid name '{identifier}'. Expected three parts separated by '/'")
    from ament_index_python import has_resource
    package, kind, name = parts
    prefix = has_resource('packages', package)
    if not prefix:
        raise CliError(f"Unknown package '{package}'")
    path = os.path.join(prefix, 'share', package, kind, f'{name}.{kind}')
    if kind not in KINDS or not os.path.isfile(path):
        # rosidl_runtime_py's message: the last path tried is the .idl one.
        idl = os.path.join(prefix, 'share', package, kind, f'{name}.idl')
        raise CliError(f"Could not find the interface '{idl}'")
    return path


class Line:
    """One line of a .msg/.srv/.action file, classified the way rosidl's parser sees it."""

    def __init__(self, package: str, text: str) -> None:
        self.text = text
        self.package = package
        stripped = text.strip()
        self.is_separator = stripped == '---'
        self.is_comment = stripped.startswith('#')
        self.code, self.comment = _split_comment(text)
        tokens = self.code.split()
        self.is_field = (not self.is_separator and not self.is_comment and len(tokens) >= 2
                         and not CONSTANT.match(self.code))
        self.field_type = tokens[0] if self.is_field else None

    @property
    def nested_type(self) -> str | None:
        if not self.field_type:
            return None
        base = self.field_type.split('[', 1)[0]
        base = base.split('<=', 1)[0]
        if base in PRIMITIVES:
            return None
        if base in LEGACY:
            return LEGACY[base]
        if '/' in base:
            package, name = base.split('/', 1)
            return f'{package}/msg/{name.rsplit("/", 1)[-1]}'
        return f'{self.package}/msg/{base}'


def _split_comment(text: str) -> tuple[str, str | None]:
    quote = None
    for index, char in enumerate(text):
        if quote:
            if char == quote:
                quote = None
        elif char in '"\'':
            quote = char
        elif char == '#':
            return text[:index], text[index:]
    return text, None


def _show(
    identifier: str, comments: bool, nested_comments: bool, level: int, context: VerbContext
) -> None:
    package = identifier.split('/')[0]
    with open(definition_path(identifier)) as handle:
        lines = [Line(package, raw.rstrip()) for raw in handle]
    for line in lines:
        text = line.text
        if not comments:
            if not text or line.is_comment:
                continue
            if line.is_field and line.comment is not None:
                text = line.code.strip()
        print(f'{chr(9) * level}{text}' if text else '', file=context.stdout)
        nested = line.nested_type
        if nested:
            _show(nested, nested_comments, nested_comments, level + 1, context)


def main(args: argparse.Namespace, context: VerbContext) -> int:
    identifier = args.type
    if identifier == '-':
        if sys.stdin.isatty():
            raise CliError('expected stdin pipe')
        identifier = sys.stdin.readline().strip()
    if not identifier:
        raise CliError('the passed value is empty')
    _show(identifier, args.all_comments or not args.no_comments, args.all_comments, 0, context)
    return 0
