"""ros2 pkg create: Create a new ROS 2 package."""

from __future__ import annotations

import argparse
import os

from ros2cli.verb_context import CliError, VerbContext

HELP = 'Create a new ROS 2 package'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from ros2pkg.api.create import BUILD_TYPES, DEFAULT_DESCRIPTION, DEFAULT_LICENSE

    parser.add_argument('package_name', help='The package name')
    parser.add_argument('--package-format', '--package_format', type=int, default=3,
                        choices=[2, 3],
                        help='The package.xml format.')
    parser.add_argument('--description', default=DEFAULT_DESCRIPTION,
                        help='The description given in the package.xml')
    parser.add_argument('--license', default=DEFAULT_LICENSE,
                        help='The license attached to this package; this can be an arbitrary '
                        'string, but a LICENSE file will only be generated if it is one of the '
                        "supported licenses (pass '?' to get a list)")
    parser.add_argument('--destination-directory', default=os.curdir,
                        help='Directory where to create the package directory')
    parser.add_argument('--build-type', default='ament_cmake', choices=list(BUILD_TYPES),
                        help='The build type to process the package with')
    parser.add_argument('--dependencies', nargs='+', default=[], help='list of dependencies')
    parser.add_argument('--maintainer-email',
                        help='email address of the maintainer of this package')
    parser.add_argument('--maintainer-name', default=None,
                        help='name of the maintainer of this package')
    parser.add_argument('--node-name', help='name of the empty executable')
    parser.add_argument('--library-name', help='name of the empty library')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    from ament_copyright import get_licenses

    from ros2pkg.api.create import PackageSpec, create, default_email, print_summary, validate

    licenses = {entry.spdx: entry.license_files for entry in get_licenses().values()}
    if args.license == '?':
        print('Supported licenses:\n' + '\n'.join(licenses), file=context.stdout)
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
        print('[WARNING] node name can not be equal to the library name', file=context.stderr)
        print(f'[WARNING] renaming node to {spec.node_name}', file=context.stderr)
    validate(spec)
    package_path = os.path.join(spec.destination, spec.name)
    if os.path.exists(package_path):
        raise CliError(f'Aborted! The directory already exists: {package_path} (remove it, '
                       'or choose a different destination directory or package name)')
    if os.path.exists(spec.destination) and not os.path.isdir(spec.destination):
        raise CliError(f"Invalid --destination-directory '{spec.destination}': "
                       'it is a file, not a directory')
    print_summary(spec, context.stdout)
    try:
        create(spec, licenses.get(spec.license), context.stdout)
    except OSError as error:
        raise CliError(f'unable to create the package in {spec.destination}: '
                       f'{error.strerror}') from None
    if spec.license not in licenses:
        print(f"\n[WARNING]: Unknown license '{spec.license}'.  This has been set in the "
              'package.xml, but no LICENSE file has been created.\nIt is recommended to use '
              'one of the ament license identifiers:\n' + '\n'.join(licenses), file=context.stdout)
    return 0
