"""ros2cli's verb classes under upstream's names (`ros2topic.verb.info.InfoVerb`, ...), for code
that drives a verb from Python: each delegates to the ros2cli_lite verb module of its name."""

from __future__ import annotations

import argparse
import importlib
from typing import Any


class VerbExtension:
    """A `ros2 topic` verb: add_arguments(parser, cli_name) and main(*, args)."""

    VERB = ''  # the module of ros2cli_lite.command.topic

    def _module(self) -> Any:
        return importlib.import_module(f'ros2cli_lite.command.topic.{self.VERB}')

    def add_arguments(self, parser: argparse.ArgumentParser, cli_name: str) -> None:
        # The options every graph verb of the `ros2` command has (ros2cli_lite.api).
        parser.add_argument('--spin-time', type=float, default=None)
        parser.add_argument('-s', '--use-sim-time', action='store_true')
        parser.add_argument('--no-daemon', action='store_true')
        parser.add_argument('--include-hidden-topics', action='store_true')
        self._module().add_arguments(parser)

    def main(self, *, args: argparse.Namespace) -> Any:
        """Run the verb; options missing from `args` take their defaults."""
        parser = argparse.ArgumentParser(add_help=False)
        self.add_arguments(parser, 'ros2')
        values = {action.dest: action.default for action in parser._actions}
        values['include_hidden_topics_verb'] = False
        values.update(vars(args))
        return self._module().main(argparse.Namespace(**values))
