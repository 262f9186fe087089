"""ros2 interface: list, packages, package, show, proto (definition files of the ament index)."""

from __future__ import annotations

import argparse
import os
import re
import sys

from ros2cli_lite.api import CliError

KINDS = ('msg', 'srv', 'action')
PRIMITIVES = {
    'bool', 'byte', 'char', 'float32', 'float64', 'int8', 'uint8', 'int16', 'uint16', 'int32',
    'uint32', 'int64', 'uint64', 'string', 'wstring',
}
CONSTANT = re.compile(r'^\s*\S+\s+[A-Za-z_]\w*\s*=')
LEGACY = {'Header': 'std_msgs/msg/Header', 'time': 'builtin_interfaces/msg/Time',
          'duration': 'builtin_interfaces/msg/Duration'}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(title='Commands', metavar='Call')
    p = verbs.add_parser('list', help='List all interface types available')
    p.add_argument('-m', '--only-msgs', action='store_true',
                   help='Print out only the message types')
    p.add_argument('-s', '--only-srvs', action='store_true',
                   help='Print out only the service types')
    p.add_argument('-a', '--only-actions', action='store_true',
                   help='Print out only the action types')
    p.set_defaults(_main=list_verb)
    p = verbs.add_parser('packages', help='Output a list of packages that provide interfaces')
    p.add_argument('-m', '--only-msgs', action='store_true')
    p.add_argument('-s', '--only-srvs', action='store_true')
    p.add_argument('-a', '--only-actions', action='store_true')
    p.set_defaults(_main=packages_verb)
    p = verbs.add_parser('package', help='Output a list of available interface types within one '
                         'package')
    p.add_argument('package_name', help="Name of the ROS package (e.g. 'example_interfaces')")
    p.set_defaults(_main=package_verb)
    p = verbs.add_parser('show', help='Output the interface definition')
    group = p.add_mutually_exclusive_group()
    group.add_argument('--all-comments', action='store_true',
                       help='Show all comments, including for nested interface definitions')
    group.add_argument('--no-comments', action='store_true',
                       help='Show no comments or whitespace')
    p.add_argument('type', help="Show an interface definition (e.g. "
                   "'example_interfaces/msg/String'); '-' reads it from stdin")
    p.set_defaults(_main=show_verb)
    p = verbs.add_parser('proto', help='Output an interface prototype')
    p.add_argument('type', help="Show an interface prototype (e.g. 'std_msgs/msg/String')")
    p.add_argument('--no-quotes', action='store_true', help='if true output has no outer quotes.')
    p.set_defaults(_main=proto_verb)


# --------------------------------------------------------------------------------------
# The ament index
# --------------------------------------------------------------------------------------

def interface_packages() -> dict[str, str]:
    from ament_index_python import get_resources
    return get_resources('rosidl_interfaces')


def interfaces_of(package: str) -> list[str]:
    """'kind/Name' of every interface of a package, in the index's order, without duplicates."""
    from ament_index_python import get_resource, has_resource
    if not has_resource('packages', package):
        raise CliError(f"Unknown package '{package}'")
    try:
        content, _ = get_resource('rosidl_interfaces', package)
    except LookupError:
        return []
    names: list[str] = []
    for line in content.splitlines():
        stem = line.rsplit('.', 1)[0]
        kind = stem.split('/', 1)[0]
        if kind in KINDS and '_' not in stem.split('/', 1)[-1] and stem not in names:
            names.append(stem)
    return names


def _names_by_kind(kind: str) -> dict[str, list[str]]:
    result = {}
    for package in interface_packages():
        names = sorted(n.split('/', 1)[1] for n in interfaces_of(package)
                       if n.startswith(kind + '/'))
        if names:
            result[package] = names
    return result


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
        raise CliError(f"Could not find the interface '{path}'")
    return path


# --------------------------------------------------------------------------------------
# Verbs
# --------------------------------------------------------------------------------------

def list_verb(args: argparse.Namespace) -> int:
    sections = [('Messages:', 'msg', args.only_msgs), ('Services:', 'srv', args.only_srvs),
                ('Actions:', 'action', args.only_actions)]
    only = args.only_msgs or args.only_srvs or args.only_actions
    for title, kind, chosen in sections:
        if only and not chosen:
            continue
        print(title)
        by_package = _names_by_kind(kind)
        for package in sorted(by_package):
            for name in by_package[package]:
                print(f'    {package}/{kind}/{name}')
    return 0


def packages_verb(args: argparse.Namespace) -> int:
    kinds = [k for k, chosen in (('msg', args.only_msgs), ('srv', args.only_srvs),
                                 ('action', args.only_actions)) if chosen]
    for package in sorted(interface_packages()):
        if kinds and not any(n.split('/')[0] in kinds for n in interfaces_of(package)):
            continue
        print(package)
    return 0


def package_verb(args: argparse.Namespace) -> int:
    for name in interfaces_of(args.package_name):
        print(f'{args.package_name}/{name}')
    return 0


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


def _show(identifier: str, comments: bool, nested_comments: bool, level: int) -> None:
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
        print(f'{chr(9) * level}{text}' if text else '')
        nested = line.nested_type
        if nested:
            _show(nested, nested_comments, nested_comments, level + 1)


def show_verb(args: argparse.Namespace) -> int:
    identifier = args.type
    if identifier == '-':
        if sys.stdin.isatty():
            raise CliError('expected stdin pipe')
        identifier = sys.stdin.readline().strip()
    if not identifier:
        raise CliError('the passed value is empty')
    _show(identifier, args.all_comments or not args.no_comments, args.all_comments, 0)
    return 0


def proto_verb(args: argparse.Namespace) -> int:
    from ros2cli_lite.api import import_type, message_to_yaml
    parts = args.type.split('/')
    kind = parts[1] if len(parts) == 3 else None
    interface = None
    for candidate in ([kind] if kind else KINDS):
        try:
            interface = import_type(args.type, candidate)
            break
        except ValueError:
            continue
    if interface is None:
        raise CliError('The passed interface type is invalid')
    if hasattr(interface, 'Goal'):
        instance = interface.Goal()
    elif hasattr(interface, 'Request'):
        instance = interface.Request()
    else:
        instance = interface()
    text = message_to_yaml(instance)
    print(text if args.no_quotes else f'"{text}"')
    return 0
