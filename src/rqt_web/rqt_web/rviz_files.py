"""The files the RViz page reads through the server: .rviz configs, meshes and textures.

- GET /api/rviz/config?path=FILE.rviz: the file's Global Options (Fixed Frame, Background
  Color), Displays (class, name, enabled, topic, settings), Tools and view as JSON, read
  from upstream rviz2's YAML layout; `path` must name an existing .rviz file.
- GET /api/rviz/resource?uri=package://PKG/PATH or file:///PATH: a mesh or texture file
  (.stl .dae .obj .mtl .png .jpg), package:// resolved through the ament index; nothing
  else is served.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import yaml
from aiohttp import web

RESOURCE_SUFFIXES = ('.stl', '.dae', '.obj', '.mtl', '.png', '.jpg', '.jpeg')


def read_rviz(path: str) -> dict:
    """The parts of an upstream .rviz file the page shows; ValueError naming what is wrong."""
    if not path.endswith('.rviz'):
        raise ValueError(f'path must name a .rviz file, got {path!r}')
    try:
        with open(path, encoding='utf-8') as f:
            data = yaml.safe_load(f)
    except OSError as error:
        raise ValueError(f'cannot read {path}: {error.strerror}') from None
    except yaml.YAMLError as error:
        raise ValueError(f'{path} is not YAML: {" ".join(str(error).split())}') from None
    manager = (data or {}).get('Visualization Manager') if isinstance(data, dict) else None
    if not isinstance(manager, dict):
        raise ValueError(f"{path}: no 'Visualization Manager' section")
    options = manager.get('Global Options') or {}
    background = str(options.get('Background Color', '48; 48; 48'))
    try:
        rgb = [int(v) for v in background.split(';')][:3]
    except ValueError:
        rgb = [48, 48, 48]
    views = ((manager.get('Views') or {}).get('Current') or {})
    tools = [{'class': str(t.get('Class', '')), 'topic': _topic(t)}
             for t in manager.get('Tools') or [] if isinstance(t, dict)]
    return {'tools': tools, 'path': path, 'fixed_frame': str(options.get('Fixed Frame', 'map')),
            'background': rgb, 'displays': [_display(d) for d in manager.get('Displays') or []
                                            if isinstance(d, dict)],
            'view': {k: views.get(k) for k in ('Class', 'Distance', 'Pitch', 'Yaw', 'Scale',
                                                 'X', 'Y')}}


def _topic(d: dict) -> Any:
    topic = d.get('Topic')
    return topic.get('Value') if isinstance(topic, dict) else topic


def _display(d: dict) -> dict:
    topic = _topic(d)
    qos = d.get('Topic') if isinstance(d.get('Topic'), dict) else {}
    description = d.get('Description Topic')
    if isinstance(description, dict):
        topic = description.get('Value', topic)
    return {'class': str(d.get('Class', '')), 'name': str(d.get('Name', '')),
            'enabled': bool(d.get('Value', True)), 'topic': topic,
            'alpha': d.get('Alpha', 1),
            'reliability': str(qos.get('Reliability Policy', 'Reliable')),
            'settings': {k: v for k, v in d.items() if isinstance(v, (str, int, float, bool))}}


async def config_route(request: web.Request) -> web.Response:
    try:
        return web.json_response(read_rviz(request.query.get('path', '')))
    except ValueError as error:
        raise web.HTTPBadRequest(text=f'{error}\n') from None


def resolve_resource(uri: str) -> Path:
    if uri.startswith('package://'):
        package, _, relative = uri[len('package://'):].partition('/')
        from ament_index_python.packages import PackageNotFoundError, get_package_share_directory
        try:
            path = Path(get_package_share_directory(package)) / relative
        except PackageNotFoundError:
            raise ValueError(f'package [{package}] of {uri} not found') from None
    elif uri.startswith('file://'):
        path = Path(uri[len('file://'):])
    else:
        raise ValueError(f'uri must start with package:// or file://, got {uri!r}')
    if path.suffix.lower() not in RESOURCE_SUFFIXES:
        raise ValueError(f'{uri}: only {", ".join(RESOURCE_SUFFIXES)} files are served')
    if not path.is_file():
        raise ValueError(f'{uri}: no such file ({os.fspath(path)})')
    return path


async def resource_route(request: web.Request) -> web.StreamResponse:
    try:
        return web.FileResponse(resolve_resource(request.query.get('uri', '')))
    except ValueError as error:
        raise web.HTTPNotFound(text=f'{error}\n') from None
