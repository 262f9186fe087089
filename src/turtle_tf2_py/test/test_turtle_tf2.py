"""The Jazzy tf2 tutorial pages (Python), typed as written, against real nodes and poses.

Each test runs one page's commands (`ros2 run`, `ros2 launch`, `ros2 topic echo`,
`ros2 run tf2_tools view_frames`) on its own leased domain, and checks what the learner
sees: the log lines and output the page shows, and turtle2 really driving where the page
says (poses from turtlesim, read by a probe node).
"""

from __future__ import annotations

import math
import re
import shutil
import subprocess
import time
from pathlib import Path

import pytest
from turtlesim.msg import Pose

from ws_testing import (
    RosProcess,
    TestNode,
    leased_domain,
    ros2_side_by_side,
    ros_environment,
    turtle_qos,
)

SPAWNED = r'\[listener\]: Successfully spawned turtle2'
TURTLE1_START = (5.544444561004639, 5.544444561004639)
TURTLE2_START = (4.0, 2.0)


class Turtles:
    """The latest pose of each turtle, as turtlesim publishes it."""

    def __init__(self, probe: TestNode, names: tuple[str, ...] = ('turtle1', 'turtle2')) -> None:
        self.probe = probe
        self.latest: dict[str, Pose] = {}
        for name in names:
            probe.node.create_subscription(
                Pose, f'/{name}/pose', lambda msg, name=name: self.latest.__setitem__(name, msg),
                turtle_qos())

    def xy(self, name: str) -> tuple[float, float]:
        pose = self.latest[name]
        return pose.x, pose.y

    def carrot(self) -> tuple[float, float]:
        """carrot1 of the fixed frame broadcaster: 2 m along turtle1's y axis."""
        pose = self.latest['turtle1']
        return pose.x - 2.0 * math.sin(pose.theta), pose.y + 2.0 * math.cos(pose.theta)

    def distance(self, target: tuple[float, float]) -> float:
        x, y = self.xy('turtle2')
        return math.hypot(x - target[0], y - target[1])

    def wait_until_near(self, target, within: float, timeout: float, what: str) -> float:
        """Spin until turtle2 is within `within` m of target() (a callable); seconds taken."""
        started = time.monotonic()
        self.probe.spin_until(lambda: 'turtle2' in self.latest and 'turtle1' in self.latest
                              and self.distance(target()) < within, timeout, what)
        return time.monotonic() - started

    def spin_for(self, seconds: float) -> None:
        self.probe.spin_for(seconds)


def stop_cleanly(demo: RosProcess) -> None:
    """Ctrl-C the launch: every node exits 0, none with a traceback."""
    assert demo.stop() == 0, demo.output
    out = demo.output
    assert 'Traceback' not in out and 'process has died' not in out, out


def ros2_launch(launch, *args: str) -> RosProcess:
    return launch(argv=['ros2', 'launch', 'turtle_tf2_py', *args])


def drive_turtle1(probe: TestNode, linear: float, angular: float) -> None:
    """What one arrow key press of turtle_teleop_key sends (turtlesim applies it for 1 s)."""
    from geometry_msgs.msg import Twist
    publisher = probe.node.create_publisher(Twist, '/turtle1/cmd_vel', 10)
    probe.spin_until(lambda: publisher.get_subscription_count() > 0, 10, 'turtlesim on cmd_vel')
    twist = Twist()
    twist.linear.x, twist.angular.z = linear, angular
    publisher.publish(twist)


def teleport_turtle1(probe: TestNode, x: float, y: float) -> None:
    from turtlesim.srv import TeleportAbsolute
    probe.call(TeleportAbsolute, '/turtle1/teleport_absolute',
               TeleportAbsolute.Request(x=x, y=y, theta=0.0))


# -- Writing a static broadcaster (Python) ---------------------------------------------------

STATIC_ECHO = re.compile(r'''transforms:
- header:
    stamp:
      sec: \d+
      nanosec: \d+
    frame_id: world
  child_frame_id: mystaticturtle
  transform:
    translation:
      x: 0\.0
      y: 0\.0
      z: 1\.0
    rotation:
      x: 0\.0
      y: 0\.0
      z: 0\.0
      w: 1\.0
---
''')


def test_static_broadcaster_page(launch, ros_env) -> None:
    # Three refused command lines, independent of each other: run side by side.
    usage, world, bad = ros2_side_by_side(
        ros_env,
        ['run', 'turtle_tf2_py', 'static_turtle_tf2_broadcaster', 'mystaticturtle', '0', '0'],
        ['run', 'turtle_tf2_py', 'static_turtle_tf2_broadcaster', 'world', '0', '0', '1', '0',
         '0', '0'],
        ['run', 'turtle_tf2_py', 'static_turtle_tf2_broadcaster', 'mystaticturtle', '0', 'up',
         '1', '0', '0', 'nan'])
    assert usage.returncode == 1
    assert re.search(r'^\[INFO\] \[[\d.]+\] \[logger\]: Invalid number of parameters\. Usage: \n'
                     r'\$ ros2 run turtle_tf2_py static_turtle_tf2_broadcaster child_frame_name '
                     r'x y z roll pitch yaw$', usage.stderr, re.MULTILINE), usage.stderr
    assert world.returncode == 2
    assert 'Your static turtle name cannot be "world"' in world.stderr
    assert bad.returncode == 2
    assert bad.stderr.count('\n') == 1 and "y must be a finite number (metres), got 'up'" \
        in bad.stderr, bad.stderr

    broadcaster = launch(argv=['ros2', 'run', 'turtle_tf2_py', 'static_turtle_tf2_broadcaster',
                               'mystaticturtle', '0', '0', '1', '0', '0', '0'])
    # Started after the broadcaster sent its one message: /tf_static is latched.
    time.sleep(1.0)
    echo = launch(argv=['ros2', 'topic', 'echo', '/tf_static'])
    echo.wait_for_output(STATIC_ECHO.pattern, timeout=20)
    assert broadcaster.popen.poll() is None
    assert broadcaster.stop() == 0
    assert 'Traceback' not in broadcaster.output


# -- Introduction to tf2, Writing a broadcaster / listener (Python), view_frames -------------

def test_turtle_demo_turtle2_follows_turtle1_and_view_frames(launch, ros_env, probe,
                                                             tmp_path) -> None:
    demo = ros2_launch(launch, 'turtle_tf2_demo.launch.py')
    turtles = Turtles(probe)
    demo.wait_for_output(SPAWNED, timeout=30)
    # turtle2 starts 3.9 m from turtle1 and drives up to it.
    turtles.wait_until_near(lambda: turtles.xy('turtle1'), 1.0, 20, 'turtle2 reaching turtle1')

    drive_turtle1(probe, 4.0, 1.0)  # as arrow keys would: turtle1 drives off in an arc
    probe.spin_until(lambda: turtles.distance(turtles.xy('turtle1')) > 2.5, 5,
                     'turtle1 driving away from turtle2')
    turtles.wait_until_near(lambda: turtles.xy('turtle1'), 1.0, 20,
                            'turtle2 catching up with turtle1 again')

    # view_frames, typed in a fresh directory while the demo runs; meanwhile its tf2_frames
    # service (tf2_msgs/srv/FrameGraph) answers with the frames as YAML.
    from tf2_msgs.srv import FrameGraph
    started = time.monotonic()
    view = subprocess.Popen(['ros2', 'run', 'tf2_tools', 'view_frames'], cwd=tmp_path,
                            env=ros_env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    try:
        # Asked as soon as the service appears, the buffer may not have heard /tf yet.
        for _ in range(20):
            frames = probe.call(FrameGraph, '/tf2_frames', FrameGraph.Request(), timeout=10)
            if 'turtle1' in frames.frame_yaml:
                break
            time.sleep(0.2)
        out, _ = view.communicate(timeout=60)
    finally:
        view.kill()
    has_dot = shutil.which('dot', path=ros_env.get('PATH')) is not None
    assert view.returncode == (0 if has_dot else 1), out
    assert time.monotonic() - started >= 5.0  # it listened 5 s as it says
    assert 'turtle1: \n  parent: \'world\'' in frames.frame_yaml, frames.frame_yaml
    lines = [line for line in out.splitlines() if '[view_frames]' in line]
    stamp = r'\[INFO\] \[[\d.]+\] \[view_frames\]: '
    assert re.fullmatch(stamp + r'Listening to tf data for 5\.0 seconds\.\.\.', lines[0]), out
    assert re.fullmatch(stamp + r'Generating graph\.\.\.', lines[1]), out
    assert re.fullmatch(stamp + r"Result:tf2_msgs\.srv\.FrameGraph_Response\(frame_yaml=.*",
                        lines[2]), out
    match = re.search(stamp + r'Exporting graph in (frames_\d{4}-\d\d-\d\d_\d\d\.\d\d\.\d\d'
                      r'\.pdf) file\.\.\.', out)
    assert match, out
    pdf = tmp_path / match.group(1)
    gv = pdf.with_suffix('.gv')
    if has_dot:
        assert pdf.read_bytes().startswith(b'%PDF-'), 'dot did not write a PDF'
    else:  # one line naming the missing tool and the fix; the .gv is still written
        assert f'Graphviz is not installed (no `dot` command): {gv.name} is written' in out
        assert not pdf.exists()
    graph = gv.read_text()
    assert graph.startswith('digraph G {\n')
    for child in ('turtle1', 'turtle2'):
        edge = re.search(rf'"world" -> "{child}"\[label=" Broadcaster: (\S+)\\nAverage rate: '
                         r'([\d.]+)\\nBuffer length: ([\d.]+)\\nMost recent transform: ([\d.]+)'
                         r'\\nOldest transform: ([\d.]+)\\n"\];', graph)
        assert edge, graph
        rate, length = float(edge.group(2)), float(edge.group(3))
        assert 20 < rate < 100, f'{child} is broadcast with turtlesim poses (62.5 Hz): {rate}'
        assert 3.0 < length <= 10.05, graph  # tf2 keeps 10 s
        assert float(edge.group(4)) > float(edge.group(5)) > 1e9
    assert re.search(r'"Recorded at time: [\d.]+"\[ shape=plaintext \] ;\n}->"world";\n}$',
                     graph), graph
    stop_cleanly(demo)


# -- Adding a frame (Python) ------------------------------------------------------------------

def test_adding_a_fixed_frame_turtle2_follows_carrot1(launch, probe) -> None:
    demo = ros2_launch(launch, 'turtle_tf2_fixed_frame_demo.launch.py', 'target_frame:=carrot1')
    turtles = Turtles(probe)
    demo.wait_for_output(SPAWNED, timeout=30)
    turtles.wait_until_near(turtles.carrot, 0.8, 25, 'turtle2 reaching carrot1')
    # It stops at the carrot, 2 m beside turtle1, not at turtle1 itself.
    assert turtles.distance(turtles.xy('turtle1')) > 1.2
    drive_turtle1(probe, 2.0, -1.5)
    probe.spin_until(lambda: turtles.distance(turtles.carrot()) > 2.0, 5, 'carrot1 moving away')
    turtles.wait_until_near(turtles.carrot, 0.8, 20, 'turtle2 reaching the moved carrot1')
    stop_cleanly(demo)


def test_adding_a_dynamic_frame_carrot1_circles_turtle1(launch, probe) -> None:
    from tf2_msgs.msg import TFMessage
    demo = ros2_launch(launch, 'turtle_tf2_dynamic_frame_demo.launch.py')
    turtles = Turtles(probe)
    carrots = []
    probe.node.create_subscription(
        TFMessage, '/tf', lambda msg: carrots.extend(
            t for t in msg.transforms if t.child_frame_id == 'carrot1'), 100)
    demo.wait_for_output(SPAWNED, timeout=30)
    probe.spin_until(lambda: len(carrots) >= 20, 10, '2 s of carrot1 transforms')
    for t in carrots:
        assert t.header.frame_id == 'turtle1'
        seconds = t.header.stamp.sec + t.header.stamp.nanosec * 1e-9
        # 10 m from turtle1, half a turn per second.
        assert t.transform.translation.x == pytest.approx(10 * math.sin(seconds * math.pi),
                                                          abs=1e-3)
        assert t.transform.translation.y == pytest.approx(10 * math.cos(seconds * math.pi),
                                                          abs=1e-3)
    # turtle2 chases it: it leaves its spawn point.
    probe.spin_until(lambda: 'turtle2' in turtles.latest and math.dist(
        turtles.xy('turtle2'), TURTLE2_START) > 1.0, 10, 'turtle2 chasing carrot1')
    assert 'Could not transform' not in demo.output.split('Successfully spawned')[1]
    stop_cleanly(demo)


# -- Using time (C++ page, Python listener variant) ---------------------------------------

def test_using_time_now_fails_without_timeout_and_works_with_one(launch) -> None:
    # Side by side, the fixed run in a domain of its own: the two overlap their start-up.
    with leased_domain() as other:
        fixed_probe = TestNode(other)
        demo = ros2_launch(launch, 'turtle_tf2_using_time_demo.launch.py', 'timeout:=0.0')
        fixed = launch(argv=['ros2', 'launch', 'turtle_tf2_py',
                             'turtle_tf2_using_time_demo.launch.py'],  # waits up to 50 ms
                       env=ros_environment(other))
        try:
            turtles = Turtles(fixed_probe)
            demo.wait_for_output(
                r'\[INFO\] \[[\d.]+\] \[listener\]: Could not transform turtle2 to turtle1: '
                r'Lookup would require extrapolation into the future\.  Requested time [\d.]+ '
                r'but the latest data is at time [\d.]+, when looking up transform from frame '
                r'\[turtle1\] to frame \[turtle2\]', timeout=40)
            stop_cleanly(demo)

            fixed.wait_for_output(SPAWNED, timeout=30)
            turtles.wait_until_near(lambda: turtles.xy('turtle1'), 1.0, 20,
                                    'turtle2 reaching turtle1')
            stop_cleanly(fixed)
        finally:
            fixed.stop()  # within the lease of its domain
            fixed_probe.close()


# -- Traveling in time (C++ page, Python listener variant) --------------------------------

def test_time_travel_turtle2_goes_where_carrot1_was_5_s_ago(launch, probe) -> None:
    demo = ros2_launch(launch, 'turtle_tf2_time_travel_demo.launch.py')
    turtles = Turtles(probe)
    demo.wait_for_output(SPAWNED, timeout=30)
    turtles.wait_until_near(turtles.carrot, 0.8, 30, 'turtle2 reaching carrot1')
    old_carrot = turtles.carrot()
    teleport_turtle1(probe, 2.0, 2.0)
    moved = time.monotonic()
    probe.spin_until(lambda: math.dist(turtles.carrot(), (2.0, 4.0)) < 0.01, 5,
                     'turtle1 teleported')
    # For the next 5 s carrot1's past is where it was: turtle2 stays there...
    while time.monotonic() - moved < 3.5:
        turtles.spin_for(0.25)
        assert turtles.distance(old_carrot) < 1.0, 'turtle2 left before 5 s had passed'
    # ...then it heads to where carrot1 went.
    turtles.wait_until_near(lambda: (2.0, 4.0), 0.8, 25, 'turtle2 reaching the new carrot1')
    assert time.monotonic() - moved > 5.0
    stop_cleanly(demo)


def test_tutorial_files_are_installed() -> None:
    from ament_index_python.packages import get_package_share_directory
    share = Path(get_package_share_directory('turtle_tf2_py'))
    for name in ('turtle_tf2_demo', 'turtle_tf2_fixed_frame_demo',
                 'turtle_tf2_dynamic_frame_demo', 'turtle_tf2_using_time_demo',
                 'turtle_tf2_time_travel_demo'):
        assert (share / 'launch' / f'{name}.launch.py').is_file()
    import yaml
    rviz = yaml.safe_load((share / 'rviz' / 'turtle_rviz.rviz').read_text())
    manager = rviz['Visualization Manager']
    assert manager['Global Options']['Fixed Frame'] == 'world'
    assert [d['Class'] for d in manager['Displays']] == ['rviz_default_plugins/Grid',
                                                          'rviz_default_plugins/TF']


def test_view_frames_without_tf_data_and_with_output_name(ros_env, tmp_path) -> None:
    # A run and a refused command line, independent: side by side.
    done, bad = ros2_side_by_side(
        ros_env, ['run', 'tf2_tools', 'view_frames', '-t', '0.5', '-o', str(tmp_path / 'empty')],
        ['run', 'tf2_tools', 'view_frames', '-t', 'soon'], timeout=60)
    assert 'Listening to tf data for 0.5 seconds...' in done.stderr, done.stderr
    assert f'Exporting graph in {tmp_path}/empty.pdf file...' in done.stderr
    assert (tmp_path / 'empty.gv').read_text() == 'digraph G { "No tf data received" }'
    assert bad.returncode == 2
    assert "view_frames: error: argument --wait-time/-t: invalid float value: 'soon'" \
        in bad.stderr
