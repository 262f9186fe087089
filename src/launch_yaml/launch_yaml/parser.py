"""Parser: the YAML front end (`launch: [...]`), from a path or an open stream."""

from __future__ import annotations

import os
from typing import IO, Any

import yaml

from launch import frontend
from launch_yaml.entity import Entity


class Parser(frontend.Parser):
    @classmethod
    def load(cls, file: str | os.PathLike | IO[Any]) -> tuple[Entity, Parser]:
        if isinstance(file, (str, bytes, os.PathLike)):
            with open(file, encoding='utf-8') as stream:
                tree = yaml.safe_load(stream)
        else:
            tree = yaml.safe_load(file)
        if not isinstance(tree, dict) or len(tree) != 1:
            raise RuntimeError('Expected only one root')
        ((type_name, body),) = tree.items()
        return Entity(body, type_name), cls()

    @classmethod
    def get_file_extensions(cls) -> set[str]:
        return {'launch.yaml', 'launch.yml', 'yaml', 'yml', 'launch'}
