"""RViz page: frames per second and /joint_states-to-screen latency (issue 23's bars).

    scripts/ws python bench/rviz.py [--seconds 10]      (or scripts/bench --only rviz)

robot_state_publisher with the r2d2 URDF; a probe publishes /joint_states at 50 Hz, the head's
swivel angle stepping by 0.01 rad each message, and 100 extra TF frames at 50 Hz. The RViz
page (headless Chromium, fixed frame `axis`) records, on each animation frame, the head's yaw
it draws; a message's latency is from its publication (wall clock) to the first frame drawn
with its angle. Chromium renders without a GPU here (SwiftShader): the frame rate is the
software renderer's.

Then the PointCloud2 case, on a second page with a PointCloud2 display: the probe publishes a
cloud of 100,000 points (x, y, z, packed rgb: 1.6 MB) at 10 Hz; the page's frames per second,
the clouds per second it drew and those it received (a cloud that came while the previous
one was not drawn yet is skipped).
"""

from __future__ import annotations

import argparse
import math
import time

from common import Row, Session, percentile, session, verdict
from rqt_browser import chromium_missing, launch_browser, start_rqt

SECONDS = 10.0
RATE_HZ = 50.0
STEP = 0.01  # rad of swivel per message
EXTRA_FRAMES = 100
LATENCY_GOAL_MS = 100.0
CLOUD_POINTS = 100_000
CLOUD_HZ = 10.0
COUNTS = '''(() => { const c = window.rviz.clouds.PointCloud2;
  return [window.rviz.renders, c.drawn, c.received]; })()'''

RECORDER = '''() => {
  window.benchSeen = [];
  let last = null;
  const tick = () => {
    const head = window.rviz && window.rviz.frames && window.rviz.frames.head;
    if (head && !head.error) {
      const [x, y, z, w] = head.rotation;
      const yaw = Math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
      if (yaw !== last) { window.benchSeen.push([Date.now(), yaw]); last = yaw; }
    }
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
}'''


def run(current: Session, seconds: float = SECONDS, extra_frames: int = EXTRA_FRAMES
        ) -> tuple[list[Row], dict]:
    if chromium_missing():
        return [Row('rviz', 'page', 'skipped', '', str(chromium_missing()))], {}
    from ament_index_python.packages import get_package_share_directory
    from playwright.sync_api import sync_playwright
    from sensor_msgs.msg import JointState
    from tf2_msgs.msg import TFMessage

    share = get_package_share_directory('urdf_tutorial_r2d2')
    # The URDF file as robot_state_publisher's (deprecated) argument, as the r2d2 demo does.
    current.start_argv(['ros2', 'run', 'robot_state_publisher', 'robot_state_publisher',
                        f'{share}/r2d2.urdf.xml'])
    server, _ = start_rqt(current.env, current.log_dir / 'rqt-state')
    probe = current.probe('rviz_bench')
    joints = probe.node.create_publisher(JointState, '/joint_states', 10)
    tf = probe.node.create_publisher(TFMessage, '/tf', 100)
    sent: list[tuple[float, float]] = []
    try:
        with sync_playwright() as playwright:
            browser = launch_browser(playwright)
            page = browser.new_page(viewport={'width': 1280, 'height': 900})
            page.goto(server.page_url('/rviz', config=f'{share}/r2d2.rviz', fixed_frame='axis'))
            page.wait_for_function('() => window.rviz && window.rviz.ready', timeout=40000)
            page.evaluate(RECORDER)
            renders_before = page.evaluate('window.rviz.renders')
            started = time.monotonic()
            step = 0
            while time.monotonic() - started < seconds:
                step += 1
                angle = math.remainder(step * STEP, 2 * math.pi)
                stamp = probe.node.get_clock().now().to_msg()
                joints.publish(JointState(header=_header(stamp), name=['tilt', 'swivel',
                                          'periscope'], position=[0.0, angle, 0.0]))
                sent.append((time.time(), angle))
                tf.publish(TFMessage(transforms=[_frame(stamp, i, step) for i in
                                                 range(extra_frames)]))
                probe.spin_for(1.0 / RATE_HZ)
            elapsed = time.monotonic() - started
            page.wait_for_timeout(500)
            renders = page.evaluate('window.rviz.renders') - renders_before
            seen = page.evaluate('window.benchSeen')
            page.close()
            cloud_rows, cloud_extra = _cloud(current, server, probe, browser, seconds)
            browser.close()
    finally:
        probe.close()
        server.stop()
    latencies = _latencies(sent, seen)
    fps = renders / elapsed
    p50, p95 = percentile(latencies, 50), percentile(latencies, 95)
    rows = [Row('rviz', f'frames per second (r2d2 + {extra_frames} TF frames at 50 Hz)',
                f'{fps:.1f}'),
            Row('rviz', f'/joint_states to the model drawn, p50 ({extra_frames} extra frames)',
                f'{p50:.0f} ms'),
            Row('rviz', '/joint_states to the model drawn, p95', f'{p95:.0f} ms',
                f'<= {LATENCY_GOAL_MS:.0f} ms', verdict(p95 <= LATENCY_GOAL_MS)),
            Row('rviz', 'messages seen drawn', f'{len(latencies)} of {len(sent)}'),
            *cloud_rows]
    return rows, {'rviz_fps': fps, 'rviz_latency_ms': latencies, **cloud_extra}


def _cloud(current: Session, server, probe, browser, seconds: float) -> tuple[list[Row], dict]:
    """PointCloud2: CLOUD_POINTS points at CLOUD_HZ; the page's frame rate and clouds drawn."""
    import numpy as np
    import yaml
    from sensor_msgs.msg import PointCloud2, PointField

    config = current.log_dir / 'cloud.rviz'
    config.write_text(yaml.safe_dump({'Visualization Manager': {
        'Global Options': {'Fixed Frame': 'map'},
        'Displays': [{'Class': 'rviz_default_plugins/Grid', 'Name': 'Grid', 'Value': True},
                     {'Class': 'rviz_default_plugins/PointCloud2', 'Name': 'PointCloud2',
                      'Value': True, 'Topic': {'Value': '/bench_cloud'}, 'Size (m)': 0.03}]}}))
    rng = np.random.default_rng(0)
    points = np.zeros(CLOUD_POINTS, dtype=[('x', '<f4'), ('y', '<f4'), ('z', '<f4'),
                                           ('rgb', '<u4')])
    points['x'], points['y'] = rng.uniform(-5, 5, CLOUD_POINTS), rng.uniform(-5, 5, CLOUD_POINTS)
    points['z'] = np.sin(points['x']) * np.cos(points['y'])
    level = ((points['z'] + 1) * 127.5).astype(np.uint32)
    points['rgb'] = (level << 16) | ((255 - level) << 8) | 128
    msg = PointCloud2(height=1, width=CLOUD_POINTS, point_step=16, row_step=16 * CLOUD_POINTS,
                      is_dense=True, fields=[
                          PointField(name=n, offset=4 * i, datatype=PointField.FLOAT32, count=1)
                          for i, n in enumerate(('x', 'y', 'z', 'rgb'))])
    msg.header.frame_id = 'map'
    msg.data = points.tobytes()
    publisher = probe.node.create_publisher(PointCloud2, '/bench_cloud', 5)
    page = browser.new_page(viewport={'width': 1280, 'height': 900})
    page.goto(server.page_url('/rviz', config=str(config)))
    page.wait_for_function('() => window.rviz && window.rviz.ready', timeout=40000)
    # Until the page draws its first cloud (its subscription is made when it opens).
    deadline = time.monotonic() + 30
    while page.evaluate('window.rviz.clouds.PointCloud2.drawn') == 0:
        if time.monotonic() > deadline:
            raise RuntimeError('the page drew no PointCloud2 within 30 s')
        msg.header.stamp = probe.node.get_clock().now().to_msg()
        publisher.publish(msg)
        probe.spin_for(1.0 / CLOUD_HZ)
    before = page.evaluate(COUNTS)
    started = time.monotonic()
    published = 0
    while time.monotonic() - started < seconds:
        msg.header.stamp = probe.node.get_clock().now().to_msg()
        publisher.publish(msg)
        published += 1
        probe.spin_for(max(0.0, started + published / CLOUD_HZ - time.monotonic()))
    elapsed = time.monotonic() - started
    after = page.evaluate(COUNTS)
    drawn_points = page.evaluate('window.rviz.clouds.PointCloud2.points')
    page.close()
    fps = (after[0] - before[0]) / elapsed
    clouds = (after[1] - before[1]) / elapsed
    received = (after[2] - before[2]) / elapsed
    label = f'PointCloud2 {CLOUD_POINTS:,} points at {CLOUD_HZ:.0f} Hz'
    return [Row('rviz', f'frames per second ({label})', f'{fps:.1f}'),
            Row('rviz', f'clouds drawn per second ({label})', f'{clouds:.1f}',
                f'of {published / elapsed:.1f} published'),
            Row('rviz', 'clouds received by the page per second', f'{received:.1f}'),
            Row('rviz', 'points drawn per cloud', f'{drawn_points:,}')], \
        {'rviz_cloud_fps': fps, 'rviz_clouds_per_s': clouds,
         'rviz_clouds_received_per_s': received}


def _header(stamp):
    from std_msgs.msg import Header
    return Header(stamp=stamp, frame_id='')


def _frame(stamp, index: int, step: int):
    from geometry_msgs.msg import TransformStamped
    t = TransformStamped()
    t.header.stamp = stamp
    t.header.frame_id = 'axis'
    t.child_frame_id = f'extra_{index}'
    t.transform.translation.x = math.cos(index + step * 0.01) * 2.0
    t.transform.translation.y = math.sin(index + step * 0.01) * 2.0
    t.transform.rotation.w = 1.0
    return t


def _latencies(sent: list[tuple[float, float]], seen: list[list[float]]) -> list[float]:
    """ms from each message to the first animation frame showing its angle (to 1e-4 rad)."""
    out = []
    for at, angle in sent:
        for shown_ms, yaw in seen:
            same = abs(math.remainder(yaw - angle, 2 * math.pi)) < 1e-4
            if shown_ms / 1000 >= at - 0.005 and same:
                out.append(max(0.0, shown_ms - at * 1000))
                break
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--seconds', type=float, default=SECONDS)
    parser.add_argument('--extra-frames', type=int, default=EXTRA_FRAMES,
                        help='TF frames published besides the robot (0-1000)')
    options = parser.parse_args()
    if not 1.0 <= options.seconds <= 600.0:
        parser.error('--seconds must be between 1 and 600')
    if not 0 <= options.extra_frames <= 1000:
        parser.error('--extra-frames must be between 0 and 1000')
    with session('rviz') as current:
        rows, _ = run(current, options.seconds, options.extra_frames)
    for row in rows:
        print(f'{row.metric}: {row.value} {row.target} {row.verdict}'.rstrip())


if __name__ == '__main__':
    main()
