"""ros2 pkg: create, executables, list, prefix, xml."""

from __future__ import annotations

import argparse
import os
import sys

from ros2cli_lite.api import CliError

PACKAGE_NOT_FOUND = 'Package not found'
PACKAGE_XML_NOT_FOUND = 'Package XML manifest not found'
PACKAGE_XML_TAG_NOT_FOUND = 'XML tag not found'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from ros2pkg.create import BUILD_TYPES, DEFAULT_DESCRIPTION, DEFAULT_LICENSE

    verbs = parser.add_subparsers(title='Commands', metavar='Call')

    def verb(name: str, func, help_text: str) -> argparse.ArgumentParser:
        p = verbs.add_parser(name, help=help_text, description=help_text)
        p.set_defaults(_main=func)
        return p

    p = verb('create', create_verb, 'Create a new ROS 2 package')
    p.add_argument('package_name', help='The package name')
    p.add_argument('--package-format', '--package_format', type=int, default=3, choices=[2, 3],
                   help='The package.xml format.')
    p.add_argument('--description', default=DEFAULT_DESCRIPTION,
                   help='The description given in the package.xml')
    p.add_argument('--license', default=DEFAULT_LICENSE,
                   help='The license attached to this package; this can be an arbitrary '
                   'string, but a LICENSE file will only be generated if it is one of the '
                   "supported licenses (pass '?' to get a list)")
    p.add_argument('--destination-directory', default=os.curdir,
                   help='Directory where to create the package directory')
    p.add_argument('--build-type', default='ament_cmake', choices=list(BUILD_TYPES),
                   help='The build type to process the package with')
    p.add_argument('--dependencies', nargs='+', default=[], help='list of dependencies')
    p.add_argument('--maintainer-email', help='email address of the maintainer of this package')
    p.add_argument('--maintainer-name', default=None,
                   help='name of the maintainer of this package')
    p.add_argument('--node-name', help='name of the empty executable')
    p.add_argument('--library-name', help='name of the empty library')

    p = verb('executables', executables_verb, 'Output a list of package specific executables')
    p.add_argument('package_name', nargs='?', help='The package name')
    p.add_argument('--full-path', action='store_true', help='Show full path of each executable')
    verb('list', list_verb, 'Output a list of available packages')
    p = verb('prefix', prefix_verb, 'Output the prefix path of a package')
    p.add_argument('package_name', help='The package name')
    p.add_argument('--share', action='store_true', help='Show share directory for the package')
    p = verb('xml', xml_verb, 'Output the XML of the package manifest or a specific tag')
    p.add_argument('package_name', help='The package name')
    p.add_argument('-t', '--tag', help="The XML tag to output (e.g. 'version')")


def create_verb(args: argparse.Namespace) -> int:
    from ament_copyright import get_licenses

    from ros2pkg.create import PackageSpec, create, default_email, print_summary, validate

    licenses = {entry.spdx: entry.license_files for entry in get_licenses().values()}
    if args.license == '?':
        print('Supported licenses:\n' + '\n'.join(licenses))
        return 0
    spec = PackageSpec(
        name=args.package_name, build_type=args.build_type,
        package_format=args.package_format, description=args.description,
        license=args.license, dependencies=list(args.dependencies),
        node_name=args.node_name, library_name=args.library_name,
        destination=args.destination_directory)
    if args.maintainer_name is not None:
        spec.maintainer_name = args.maintainer_name
    spec.maintainer_email = args.maintainer_email or default_email(spec.maintainer_name)
    if spec.node_name and spec.node_name == spec.library_name:
        spec.node_name += '_node'
        print('[WARNING] node name can not be equal to the library name', file=sys.stderr)
        print(f'[WARNING] renaming node to {spec.node_name}', file=sys.stderr)
    validate(spec)
    package_path = os.path.join(spec.destination, spec.name)
    if os.path.exists(package_path):
        raise CliError(f'Aborted! The directory already exists: {package_path} (remove it, '
                       'or choose a different destination directory or package name)')
    if os.path.exists(spec.destination) and not os.path.isdir(spec.destination):
        raise CliError(f"Invalid --destination-directory '{spec.destination}': "
                       'it is a file, not a directory')
    print_summary(spec)
    try:
        create(spec, licenses.get(spec.license))
    except OSError as error:
        raise CliError(f'unable to create the package in {spec.destination}: '
                       f'{error.strerror}') from None
    if spec.license not in licenses:
        print(f"\n[WARNING]: Unknown license '{spec.license}'.  This has been set in the "
              'package.xml, but no LICENSE file has been created.\nIt is recommended to use '
              'one of the ament license identifiers:\n' + '\n'.join(licenses))
    return 0


def _package_names() -> list[str]:
    from ros2pkg.api import get_package_names
    return sorted(get_package_names())


def executables_verb(args: argparse.Namespace) -> int:
    from ros2cli_lite.command.run import executables

    names = _package_names() if args.package_name is None else [args.package_name]
    for name in names:
        _, paths = executables(name)
        for path in paths:
            print(path if args.full_path else f'{name} {os.path.basename(path)}')
    return 0


def list_verb(args: argparse.Namespace) -> int:
    for name in _package_names():
        print(name)
    return 0


def _share_directory(name: str) -> str:
    from ament_index_python.packages import PackageNotFoundError, get_package_share_directory
    try:
        return get_package_share_directory(name)
    except (PackageNotFoundError, ValueError):
        raise CliError(PACKAGE_NOT_FOUND) from None


def prefix_verb(args: argparse.Namespace) -> int:
    from ros2pkg.api import get_prefix_path
    if args.share:
        print(_share_directory(args.package_name))
        return 0
    prefix = get_prefix_path(args.package_name)
    if prefix is None:
        raise CliError(PACKAGE_NOT_FOUND)
    print(prefix)
    return 0


def xml_verb(args: argparse.Namespace) -> int:
    import xml.etree.ElementTree as ET

    manifest = os.path.join(_share_directory(args.package_name), 'package.xml')
    if not os.path.isfile(manifest):
        raise CliError(PACKAGE_XML_NOT_FOUND)
    try:
        tree = ET.parse(manifest)
    except ET.ParseError as error:
        raise CliError(f'{manifest}: not well-formed XML ({error})') from None
    if args.tag is None:
        ET.dump(tree)
        return 0
    try:
        elements = tree.getroot().findall(args.tag)
    except SyntaxError as error:
        raise CliError(f"Invalid --tag '{args.tag}': {error}") from None
    if not elements:
        raise CliError(PACKAGE_XML_TAG_NOT_FOUND)
    for element in elements:
        print(element.text)
    return 0
