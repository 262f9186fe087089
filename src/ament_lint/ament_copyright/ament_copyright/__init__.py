"""ament_copyright: copyright notice and license header checks, and the license texts.

`get_licenses()` keeps upstream's shape ({key: entry with .name, .spdx, .file_headers,
.license_files}) because `ros2 pkg create --license` reads it.
"""

from __future__ import annotations

import os
from typing import NamedTuple

_LICENSE_DIR = os.path.join(os.path.dirname(__file__), 'licenses')
# (key, name, SPDX identifier) in the order `ros2 pkg create` lists them.
_LICENSES = (
    ('apache2', 'Apache License, Version 2.0', 'Apache-2.0'),
    ('boost1', 'Boost Software License - Version 1.0', 'BSL-1.0'),
    ('bsd2', 'BSD License 2.0', 'BSD-2.0'),
    ('bsd_3clause', '3-Clause BSD License', 'BSD-3-Clause'),
    ('bsd_2clause', '2-Clause BSD License', 'BSD-2-Clause'),
    ('mit', 'MIT License', 'MIT'),
    ('mit0', 'MIT-0 License', 'MIT-0'),
    ('gplv3', 'GNU General Public License 3.0', 'GPL-3.0-only'),
    ('lgplv3', 'GNU Lesser General Public License 3.0', 'LGPL-3.0-only'),
)


class LicenseEntry(NamedTuple):
    name: str
    spdx: str
    file_headers: list[str]
    license_files: list[str]


def _read(key: str, kind: str) -> list[str]:
    with open(os.path.join(_LICENSE_DIR, f'{key}_{kind}.txt'), encoding='utf-8') as text:
        return [text.read()]


def get_licenses() -> dict[str, LicenseEntry]:
    return {key: LicenseEntry(name, spdx, _read(key, 'header'), _read(key, 'license'))
            for key, name, spdx in _LICENSES}
