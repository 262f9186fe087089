"""The files the pages are made of: each page's HTML shell, /static/ and /vendor/.

- GET / and /{page}: static/page.html with the page's name and title filled in (a page
  instance.PAGES does not know is 404).
- GET /static/{name}: this package's scripts and styles, in folders too (the RViz page's ES
  modules are static/rviz/...), nothing outside static/.
- GET /vendor/{name}: the browser libraries `npm ci` installed at setup (package.json of
  rqt_web), under the names the pages ask for.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

from aiohttp import web

from rqt_web import instance

STATIC = Path(__file__).resolve().parent / 'static'
# The browser libraries scripts/setup installed with `npm ci` (package.json of rqt_web).
VENDOR_FILES = {
    'cytoscape.min.js': 'cytoscape/dist/cytoscape.min.js',
    'cytoscape-dagre.js': 'cytoscape-dagre/dist/cytoscape-dagre.js',
    'cytoscape-svg.js': 'cytoscape-svg/cytoscape-svg.js',
    # three.js for the RViz page: the ES modules, loaded through an import map
    'three.module.js': 'three/build/three.module.js',
    'three.core.js': 'three/build/three.core.js',
    'OrbitControls.js': 'three/examples/jsm/controls/OrbitControls.js',
    'STLLoader.js': 'three/examples/jsm/loaders/STLLoader.js',
    # Mesh loaders under their examples/jsm layout, so their relative imports resolve.
    'addons/loaders/ColladaLoader.js': 'three/examples/jsm/loaders/ColladaLoader.js',
    'addons/loaders/TGALoader.js': 'three/examples/jsm/loaders/TGALoader.js',
    'addons/loaders/collada/ColladaParser.js':
        'three/examples/jsm/loaders/collada/ColladaParser.js',
    'addons/loaders/collada/ColladaComposer.js':
        'three/examples/jsm/loaders/collada/ColladaComposer.js',
    'addons/loaders/OBJLoader.js': 'three/examples/jsm/loaders/OBJLoader.js',
}


def vendor_dir() -> Path:
    return Path(os.environ.get('RQT_WEB_JS_DIR', Path(sys.prefix) / 'rqt_web_js')) / 'node_modules'


def vendor_installed() -> bool:
    """Whether every browser library is there (the Node Graph page says so when not)."""
    return all((vendor_dir() / p).is_file() for p in VENDOR_FILES.values())


async def page(request: web.Request) -> web.Response:
    name = request.match_info.get('page') or 'index'
    if name not in instance.PAGES:
        raise web.HTTPNotFound(text=f'no page {name!r}')
    shell = (STATIC / 'page.html').read_text()
    html = shell.replace('{{PAGE}}', name).replace('{{TITLE}}', instance.PAGES[name][1])
    return web.Response(text=html, content_type='text/html',
                        headers={'Cache-Control': 'no-store'})


async def static_file(request: web.Request) -> web.FileResponse:
    name = request.match_info['name']
    path = STATIC / name
    # Folders too (the RViz page's ES modules are static/rviz/...), nothing outside STATIC.
    # .js goes out as text/javascript (mimetypes), which module scripts require.
    if name.startswith('/') or '..' in name.split('/') or not path.is_file():
        raise web.HTTPNotFound()
    return web.FileResponse(path)


async def vendor_file(request: web.Request) -> web.FileResponse:
    relative = VENDOR_FILES.get(request.match_info['name'])
    path = vendor_dir() / relative if relative else None
    if path is None or not path.is_file():
        raise web.HTTPNotFound(text='browser library not installed: run scripts/setup '
                               '(it needs npm)')
    return web.FileResponse(path)
