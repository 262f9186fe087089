"""ros2 bag: record, play, burst, info, reindex, convert and list (ros2bag.verb.<verb>)."""

from __future__ import annotations

import argparse
import importlib

VERBS = {
    'record': 'Record ROS data to a bag',
    'play': 'Play back ROS data from a bag',
    'info': 'Print information about a bag to the screen',
    'reindex': 'Reconstruct metadata file for a bag',
    'burst': 'Burst data from a bag',
    'convert': 'Given an input bag, write out a new bag with different settings',
    'list': 'Print information about available plugins to the screen',
}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(title='Commands', metavar='Call')
    for name, help_text in VERBS.items():
        verb = verbs.add_parser(name, help=help_text, description=help_text)
        importlib.import_module(f'ros2bag.verb.{name}').add_arguments(verb)
