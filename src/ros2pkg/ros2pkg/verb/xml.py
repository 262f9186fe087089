"""ros2 pkg xml: Output the XML of the package manifest or a specific tag."""

from __future__ import annotations

import argparse
import os

from ros2cli.verb_context import CliError, VerbContext

from ros2pkg.api import share_directory

PACKAGE_XML_NOT_FOUND = 'Package XML manifest not found'
PACKAGE_XML_TAG_NOT_FOUND = 'XML tag not found'
HELP = 'Output the XML of the package manifest or a specific tag'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('package_name', help='The package name')
    parser.add_argument('-t', '--tag', help="The XML tag to output (e.g. 'version')")


def main(args: argparse.Namespace, context: VerbContext) -> int:
    import xml.etree.ElementTree as ET

    manifest = os.path.join(share_directory(args.package_name), 'package.xml')
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
        print(element.text, file=context.stdout)
    return 0
