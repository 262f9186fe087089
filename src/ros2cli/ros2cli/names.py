"""ROS names as every command shows them: hidden names, full node names, listings."""

from __future__ import annotations

from ros2cli.verb_context import VerbContext


def is_hidden(name: str) -> bool:
    """A topic/service name is hidden when any of its `/` tokens starts with `_`."""
    return any(token.startswith('_') for token in name.split('/'))


def is_hidden_node(name: str) -> bool:
    return name.startswith('_')


def print_names(names: list[str], count_only: bool, context: VerbContext) -> None:
    """One name a line, or with `count_only` (the `-c` of list/find verbs) just how many."""
    if count_only:
        print(len(names), file=context.stdout)
    else:
        for name in names:
            print(name, file=context.stdout)


def full_node_name(name: str, namespace: str) -> str:
    return namespace.rstrip('/') + '/' + name
