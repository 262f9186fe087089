"""The `ros2 topic` verbs, one module each (HELP, add_arguments, main, runs_in_daemon), with
upstream's class of each verb (`ros2topic.verb.info.InfoVerb`, ...) for code that drives a verb
from Python: the class runs its module's main()."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from ros2cli.verb_context import VerbContext


class VerbExtension:
    """A `ros2 topic` verb: add_arguments(parser, cli_name) and main(*, args)."""

    def _module(self) -> Any:
        return sys.modules[type(self).__module__]

    def add_arguments(self, parser: argparse.ArgumentParser, cli_name: str) -> None:
        # The options every graph verb of the `ros2` command has (ros2cli.command.add_graph_verb).
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
        return self._module().main(argparse.Namespace(**values), VerbContext.here())
