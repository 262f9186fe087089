"""Write requirements.lock from what .venv holds: `scripts/ws python tools/freeze_lock.py`.

Unlike `pip freeze`, this leaves out the egg-info records that the ROS wheels carry inside
them (action_msgs, rclpy, rosidl_adapter, ...): those are parts of another wheel, not
projects on the package index, and pinning them would make the install fail.
"""

from importlib import metadata
from pathlib import Path

HEADER = """\
# Exact versions of everything in .venv; scripts/setup installs this file.
# Regenerate after installing something new: scripts/ws python tools/freeze_lock.py
"""


def installable_pins() -> list[str]:
    pins = set()
    for dist in metadata.distributions():
        if str(getattr(dist, '_path', '')).endswith('.egg-info'):
            continue
        name = dist.metadata['Name']
        if name not in ('pip', 'setuptools', 'wheel'):
            pins.add(f'{name}=={dist.version}')
    return sorted(pins, key=str.lower)


if __name__ == '__main__':
    lock = Path(__file__).resolve().parent.parent / 'requirements.lock'
    lock.write_text(HEADER + '\n'.join(installable_pins()) + '\n')
    print(f'wrote {lock}')
