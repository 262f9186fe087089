"""joint_state_publisher_gui: joint_state_publisher with sliders in the browser.

The node is joint_state_publisher itself (same name, parameters, /joint_states); the sliders
are the Joint State Publisher page of the rqt web app, which publishes the chosen positions on
SLIDERS_TOPIC (a sensor_msgs/JointState) that this node takes like a `source_list` topic.
At start it prints the page's URL (and opens the browser when there is one), as rviz2 does.
"""

from __future__ import annotations

import sys
import threading

from sensor_msgs.msg import JointState

from joint_state_publisher.joint_state_publisher import JointStatePublisher
from joint_state_publisher.joint_state_publisher import main as run

SLIDERS_TOPIC = '/joint_state_publisher_gui/sliders'


def open_page() -> None:
    from rqt_web.launcher import Announcer, _open_browser

    from rqt_web import instance
    try:
        server, _started = instance.ensure_running()
    except RuntimeError as error:
        print(f'joint_state_publisher_gui: {error}', file=sys.stderr)
        return
    url = server.url('joint_state_publisher')
    announcer = Announcer('joint_state_publisher_gui', sys.argv)
    announcer.say(f'Joint State Publisher: {url}')
    _open_browser(url, announcer.say)


def add_sliders(node: JointStatePublisher) -> None:
    """The page's slider positions, taken like a source_list topic; the page opened."""
    node.create_subscription(JointState, SLIDERS_TOPIC, node.on_source, 10)
    threading.Thread(target=open_page, daemon=True).start()


def main(args: list[str] | None = None) -> None:
    run(args, setup=add_sliders)


if __name__ == '__main__':
    main()
