"""Our pose-graph files, under upstream's names: `<name>.posegraph` and `<name>.data`.

`<name>.posegraph` is JSON: {"format": "slam_toolbox_py pose graph", "version": 1,
"resolution": m, "nodes": [{"id", "pose": [x, y, yaw], "odom": [x, y, yaw], "origin": [x, y],
"stamp": s, "covariance": 3x3}], "edges": [{"i", "j", "z": [x, y, yaw], "information": 3x3,
"loop": bool}]}. `<name>.data` is a numpy .npz archive with the scans: `hits_<id>` and
`misses_<id>`, float64 (N, 2) points in the node's robot frame. Both files are written to
a temporary name and renamed, so a failed write leaves an older pair whole.
Upstream's files are boost archives of Karto's classes; these are ours, not compatible.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np

from slam_toolbox_py.mapper import Mapper, ScanNode
from slam_toolbox_py.pose_graph import Edge

FORMAT = 'slam_toolbox_py pose graph'
VERSION = 1


def paths(filename: str) -> tuple[Path, Path]:
    base = Path(os.path.expanduser(filename))
    if base.suffix in ('.posegraph', '.data'):
        base = base.with_suffix('')
    return base.with_name(base.name + '.posegraph'), base.with_name(base.name + '.data')


def write(filename: str, mapper: Mapper, resolution: float) -> None:
    """Raises OSError when the files cannot be written."""
    graph_path, data_path = paths(filename)
    graph = {
        'format': FORMAT, 'version': VERSION, 'resolution': resolution,
        'nodes': [{'id': n.id, 'pose': n.pose.tolist(), 'odom': n.odom.tolist(),
                   'origin': n.origin.tolist(), 'stamp': n.stamp,
                   'covariance': n.covariance.tolist()} for n in mapper.nodes],
        'edges': [{'i': e.i, 'j': e.j, 'z': e.z.tolist(),
                   'information': e.information.tolist(), 'loop': e.loop}
                  for e in mapper.edges],
    }
    arrays = {}
    for n in mapper.nodes:
        arrays[f'hits_{n.id}'] = n.hits
        arrays[f'misses_{n.id}'] = n.misses
    graph_tmp = graph_path.with_name(graph_path.name + '.tmp')
    data_tmp = data_path.with_name(data_path.name + '.tmp')
    with open(data_tmp, 'wb') as handle:
        np.savez_compressed(handle, **arrays)
    graph_tmp.write_text(json.dumps(graph))
    os.replace(data_tmp, data_path)
    os.replace(graph_tmp, graph_path)


def read(filename: str, mapper: Mapper) -> None:
    """Replace the mapper's graph with the files' one. Raises OSError (missing or unreadable
    files) or ValueError (not our format, inconsistent content); the mapper is then
    untouched."""
    graph_path, data_path = paths(filename)
    try:
        graph = json.loads(graph_path.read_text())
    except json.JSONDecodeError as error:
        raise ValueError(f'{graph_path} is not a pose graph: {error}') from error
    if not isinstance(graph, dict) or graph.get('format') != FORMAT:
        raise ValueError(f'{graph_path} is not a {FORMAT} file')
    if graph.get('version') != VERSION:
        raise ValueError(f'{graph_path} has version {graph.get("version")}, '
                         f'this reads {VERSION}')
    try:
        with np.load(data_path) as data:
            arrays = {key: data[key] for key in data.files}
        nodes = []
        for k, item in enumerate(graph['nodes']):
            if item['id'] != k:
                raise ValueError(f'node {k} has id {item["id"]}')
            nodes.append(ScanNode(
                k, np.array(item['odom'], float), np.array(item['pose'], float),
                np.asarray(arrays[f'hits_{k}'], float).reshape(-1, 2),
                np.asarray(arrays[f'misses_{k}'], float).reshape(-1, 2),
                np.array(item['origin'], float), float(item['stamp']),
                np.array(item['covariance'], float).reshape(3, 3)))
        edges = [Edge(int(e['i']), int(e['j']), np.array(e['z'], float),
                      np.array(e['information'], float).reshape(3, 3), bool(e['loop']))
                 for e in graph['edges']]
    except (KeyError, TypeError, IndexError) as error:
        raise ValueError(f'{graph_path} / {data_path}: missing or malformed {error}') \
            from error
    if any(not (0 <= e.i < len(nodes) and 0 <= e.j < len(nodes)) for e in edges):
        raise ValueError(f'{graph_path}: an edge names a node that does not exist')
    mapper.nodes = nodes
    mapper.edges = edges
    mapper.loop_closures = sum(e.loop for e in edges)
    mapper.start_at(None)
