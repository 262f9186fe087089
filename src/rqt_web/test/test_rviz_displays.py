"""The RViz page's PointCloud2 and Image displays, its tool belt, and DAE/OBJ meshes (RobotModel
and MESH_RESOURCE markers, frame_locked or not), in headless Chromium.

Each test publishes from an rclpy probe in the test process, reads what the page drew (its
window.rviz state and the screenshot's pixels) or, for the tools, what a click in the page
published, received by the probe's subscriptions.
Screenshots: artifacts/rqt/rviz_cloud_image.png, rviz_tools.png, rviz_meshes.png.
"""
from __future__ import annotations

import json
import math
import statistics
import urllib.request
from pathlib import Path
from typing import Any

import pytest
import yaml

from ws_testing import wait_until
from ws_testing.browser import SCREENSHOTS, chromium_missing, rviz_page, screenshot

pytestmark = pytest.mark.skipif(chromium_missing() is not None, reason=str(chromium_missing()))

def write_rviz(path: Path, fixed_frame: str, displays: list[dict], view: dict) -> Path:
    """A .rviz file in upstream rviz2's layout."""
    path.write_text(yaml.safe_dump({'Visualization Manager': {
        'Global Options': {'Fixed Frame': fixed_frame, 'Background Color': '48; 48; 48'},
        'Displays': displays, 'Views': {'Current': view}}}))
    return path


def display(cls: str, name: str, topic: str | None = None, qos: dict | None = None,
            **settings: Any) -> dict:
    d = {'Class': f'rviz_default_plugins/{cls}', 'Name': name, 'Enabled': True, 'Value': True,
         **settings}
    if topic:
        d['Topic'] = {'Value': topic, **(qos or {})}
    return d


TOP_DOWN = {'Class': 'rviz_default_plugins/TopDownOrtho', 'Scale': 60, 'X': 0, 'Y': 0}


def region(image: Any, x: float, y: float, half: int = 2) -> tuple[int, int, int]:
    """Median colour of the (2 half + 1)^2 pixels around (x, y) of a PIL image."""
    pixels = [image.getpixel((int(x) + dx, int(y) + dy))[:3]
              for dx in range(-half, half + 1) for dy in range(-half, half + 1)]
    return tuple(int(statistics.median(p[i] for p in pixels)) for i in range(3))


def near(rgb: tuple[int, ...], expected: tuple[int, ...], tolerance: int = 12) -> bool:
    return all(abs(a - b) <= tolerance for a, b in zip(rgb, expected, strict=True))


# ------------------------------------------------------------------ PointCloud2 and Image

def cloud(points: list[tuple[float, float, float]], extra: str, values: list[float | int],
          frame: str) -> Any:
    """A PointCloud2 of x, y, z and one more float32 field (`rgb` packed, or `intensity`),
    with padding: point_step 32, the extra field at offset 16 (as PCL's PointXYZRGB)."""
    import numpy as np
    from sensor_msgs.msg import PointCloud2, PointField
    data = np.zeros(len(points), dtype={'names': ['x', 'y', 'z', extra],
                                        'formats': ['<f4', '<f4', '<f4',
                                                    '<u4' if extra == 'rgb' else '<f4'],
                                        'offsets': [0, 4, 8, 16], 'itemsize': 32})
    xyz = np.array(points, dtype=np.float32)
    data['x'], data['y'], data['z'] = xyz[:, 0], xyz[:, 1], xyz[:, 2]
    data[extra] = values
    msg = PointCloud2(height=1, width=len(points), point_step=32, row_step=32 * len(points),
                      is_dense=False, fields=[
                          PointField(name=n, offset=o, datatype=PointField.FLOAT32, count=1)
                          for n, o in (('x', 0), ('y', 4), ('z', 8), (extra, 16))])
    msg.header.frame_id = frame
    msg.data = data.tobytes()
    return msg


def patch(cx: float, cy: float, size: float = 1.0, step: float = 0.02
          ) -> list[tuple[float, float, float]]:
    n = round(size / step)
    return [(cx - size / 2 + i * step, cy - size / 2 + j * step, 0.0)
            for i in range(n) for j in range(n)]


def image(encoding: str, width: int, height: int, left: bytes, right: bytes) -> Any:
    """An Image whose left half is pixel `left` and right half `right` (bytes per pixel)."""
    from sensor_msgs.msg import Image
    row = left * (width // 2) + right * (width - width // 2)
    msg = Image(height=height, width=width, encoding=encoding, step=len(row),
                data=row * height)
    msg.header.frame_id = 'camera'
    return msg


# encoding: (left pixel bytes, right pixel bytes, left RGB drawn, right RGB drawn)
IMAGES = {
    'rgb8': (bytes([255, 0, 0]), bytes([0, 0, 255]), (255, 0, 0), (0, 0, 255)),
    'bgr8': (bytes([0, 0, 255]), bytes([255, 0, 0]), (255, 0, 0), (0, 0, 255)),
    'mono8': (bytes([200]), bytes([40]), (200, 200, 200), (40, 40, 40)),
    'rgba8': (bytes([0, 255, 0, 255]), bytes([255, 255, 0, 255]), (0, 255, 0), (255, 255, 0)),
}


def test_pointcloud2_and_image_displays_draw_what_was_published(ros_env, probe, tmp_path):
    from PIL import Image as PILImage
    from sensor_msgs.msg import Image, PointCloud2

    orange = (255 << 16) | (160 << 8)
    rgb_points = patch(2.0, 0.0) + [(math.nan, 0.0, 0.0)] * 10  # NaN points are not drawn
    rgb_cloud = cloud(rgb_points, 'rgb', [orange] * len(rgb_points), 'map')
    low, high = patch(-2.0, 0.0), patch(0.0, 2.0)
    intensity_cloud = cloud(low + high, 'intensity', [5.0] * len(low) + [105.0] * len(high),
                            'map')
    config = write_rviz(tmp_path / 'sensors.rviz', 'map', [
        display('Grid', 'Grid'),
        display('PointCloud2', 'RGB cloud', '/cloud_rgb', **{'Size (m)': 0.05}),
        # A best-effort sensor: the display's Topic QoS says so, as in rviz2.
        display('PointCloud2', 'Intensity cloud', '/cloud_intensity',
                {'Reliability Policy': 'Best Effort'}, **{'Size (m)': 0.05}),
        *[display('Image', f'Image {e}', f'/image_{e}') for e in IMAGES]], TOP_DOWN)
    images = {f'/image_{e}': image(e, 40, 30, left, right)
              for e, (left, right, _, _) in IMAGES.items()}
    from rclpy.qos import qos_profile_sensor_data
    publishers = [(probe.node.create_publisher(PointCloud2, '/cloud_rgb', 5), rgb_cloud),
                  (probe.node.create_publisher(PointCloud2, '/cloud_intensity',
                                               qos_profile_sensor_data), intensity_cloud)]
    publishers += [(probe.node.create_publisher(Image, t, 5), m) for t, m in images.items()]
    # As a sensor does: every message again at 5 Hz (the page subscribes when it opens).
    probe.node.create_timer(0.2, lambda: [pub.publish(msg) for pub, msg in publishers])
    with rviz_page(ros_env, probe, config, tmp_path) as (_server, page):
        page.wait_for_function(
            '''() => window.rviz && window.rviz.ready
                && Object.values(window.rviz.clouds).every((c) => c.drawn > 0)
                && Object.values(window.rviz.images).length === 4
                && Object.values(window.rviz.images).every((i) => i.drawn > 0)''',
            timeout=40000)
        page.wait_for_timeout(300)  # a few animation frames with the clouds drawn
        state = page.evaluate('window.rviz')
        at = page.evaluate('[[2, 0], [-2, 0], [0, 2], [0, -2.5]].map(([x, y]) => '
                           'window.rviz.project(x, y, 0))')
        drawn = page.evaluate('''() => Object.fromEntries([...document.querySelectorAll(
            'canvas.rviz-image')].map((c) => [c.dataset.name, [
            Array.from(c.getContext('2d').getImageData(5, 15, 1, 1).data),
            Array.from(c.getContext('2d').getImageData(35, 15, 1, 1).data)]]))''')
        boxes = {e: page.locator(f'canvas.rviz-image[data-name="Image {e}"]')
                 .bounding_box() for e in IMAGES}
        shot = screenshot(page, 'rviz_cloud_image')
    status = state['status']
    assert all(status[n] == 'OK' for n in ['RGB cloud', 'Intensity cloud']), status
    assert state['clouds']['RGB cloud']['points'] == 2500  # the 10 NaN points dropped
    assert state['clouds']['RGB cloud']['color'] == 'rgb'
    assert state['clouds']['Intensity cloud']['points'] == 5000
    assert state['clouds']['Intensity cloud']['color'] == 'intensity'
    shown = PILImage.open(shot).convert('RGB')
    # RGB8: the packed colour as is. Intensity: rviz's rainbow, lowest red, highest magenta.
    assert near(region(shown, *at[0]), (255, 160, 0)), region(shown, *at[0])
    assert near(region(shown, *at[1]), (255, 0, 0)), region(shown, *at[1])
    assert near(region(shown, *at[2]), (255, 0, 255)), region(shown, *at[2])
    assert near(region(shown, *at[3]), (48, 48, 48)), 'no points where none were published'
    for encoding, (_, _, left, right) in IMAGES.items():
        name = f'Image {encoding}'
        assert status[name] == 'OK', status
        info = state['images'][name]
        assert (info['width'], info['height'], info['encoding']) == (40, 30, encoding)
        assert drawn[name][0][:3] == list(left) and drawn[name][1][:3] == list(right), drawn
        box = boxes[encoding]  # scaled to its panel's 320 px: the same colours on the screen
        assert box['width'] == 320 and box['height'] == pytest.approx(240, abs=1)
        middle = box['y'] + box['height'] / 2
        assert near(region(shown, box['x'] + 0.2 * box['width'], middle), left)
        assert near(region(shown, box['x'] + 0.8 * box['width'], middle), right)


# ------------------------------------------------------------------ tool belt

def graph_topics(server: Any) -> set[str]:
    with urllib.request.urlopen(server.page_url('/api/graph'), timeout=10) as response:
        return {name for name, _ in json.loads(response.read())['topics']}


def yaw_of(q: Any) -> float:
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def test_tool_belt_publishes_poses_and_points_where_the_user_clicks(ros_env, probe, tmp_path):
    from geometry_msgs.msg import PointStamped, PoseStamped, PoseWithCovarianceStamped
    from PIL import Image as PILImage

    initial = probe.collect(PoseWithCovarianceStamped, '/initialpose')
    goals = probe.collect(PoseStamped, '/goal_pose')
    points = probe.collect(PointStamped, '/clicked_point')
    config = write_rviz(tmp_path / 'tools.rviz', 'odom', [display('Grid', 'Grid')], {
        'Class': 'rviz_default_plugins/Orbit', 'Distance': 10, 'Pitch': 0.9, 'Yaw': 0.5})

    def subscriptions_seen(server) -> None:
        # The server's node has seen the probe's subscriptions: what it publishes arrives.
        wait_until(lambda: {'/initialpose', '/goal_pose', '/clicked_point'}
                   <= graph_topics(server), 20, "the probe's subscriptions in the graph")

    with rviz_page(ros_env, probe, config, tmp_path,
                   before_browser=subscriptions_seen) as (_server, page):
        page.wait_for_function('() => window.rviz && window.rviz.ready', timeout=40000)

        def drag(tool: str, start: tuple[float, float], end: tuple[float, float],
                 shot: str | None = None) -> None:
            page.click(f'#rviz-tool-{tool}')
            a = page.evaluate('([x, y]) => window.rviz.project(x, y, 0)', list(start))
            b = page.evaluate('([x, y]) => window.rviz.project(x, y, 0)', list(end))
            page.mouse.move(*a)
            page.mouse.down()
            page.mouse.move(*b, steps=6)
            if shot:
                page.wait_for_timeout(100)  # animation frames with the arrow
                screenshot(page, shot)
            page.mouse.up()

        # 2D Pose Estimate: press at (1, 1), drag towards (2, 2): yaw 45 degrees.
        drag('initialpose', (1.0, 1.0), (2.0, 2.0))
        wait_until(lambda: initial, 10, 'a message on /initialpose')
        assert page.evaluate('window.rviz.tool') == 'interact'
        # 2D Goal Pose: at (-1, 2) towards (-1, 3): yaw 90 degrees; the arrow shows.
        drag('goal', (-1.0, 2.0), (-1.0, 3.0), shot='rviz_tools')
        wait_until(lambda: goals, 10, 'a message on /goal_pose')
        arrow_at = page.evaluate('window.rviz.project(-1, 2.5, 0)')
        # Publish Point: one click at (0.5, -1.5).
        page.click('#rviz-tool-point')
        page.mouse.click(*page.evaluate('window.rviz.project(0.5, -1.5, 0)'))
        wait_until(lambda: points, 10, 'a message on /clicked_point')
        # The page notes each publication when the server's answer comes back.
        page.wait_for_function('window.rviz.published.length === 3', timeout=10000)
        published = page.evaluate('window.rviz.published')
    pose = initial[0]
    assert pose.header.frame_id == 'odom'
    assert (pose.pose.pose.position.x, pose.pose.pose.position.y) == pytest.approx(
        (1.0, 1.0), abs=0.05)
    assert pose.pose.pose.position.z == 0.0
    assert yaw_of(pose.pose.pose.orientation) == pytest.approx(math.pi / 4, abs=0.05)
    covariance = list(pose.pose.covariance)
    assert covariance[0] == covariance[7] == 0.25 and covariance[35] == 0.06853891909122467
    assert sum(abs(v) for v in covariance) == pytest.approx(0.25 + 0.25 + 0.06853891909122467)
    goal = goals[0]
    assert goal.header.frame_id == 'odom'
    assert (goal.pose.position.x, goal.pose.position.y) == pytest.approx((-1.0, 2.0), abs=0.05)
    assert yaw_of(goal.pose.orientation) == pytest.approx(math.pi / 2, abs=0.05)
    point = points[0]
    assert point.header.frame_id == 'odom'
    assert (point.point.x, point.point.y, point.point.z) == pytest.approx((0.5, -1.5, 0.0),
                                                                          abs=0.05)
    assert [p['topic'] for p in published] == ['/initialpose', '/goal_pose', '/clicked_point']
    assert len(initial) == len(goals) == len(points) == 1
    # While dragging, the goal's arrow was drawn (green) along its direction.
    shown = PILImage.open(SCREENSHOTS / 'rviz_tools.png').convert('RGB')
    green = [(x, y) for x in range(int(arrow_at[0]) - 15, int(arrow_at[0]) + 16)
             for y in range(int(arrow_at[1]) - 15, int(arrow_at[1]) + 16)
             if (p := shown.getpixel((x, y)))[1] > 200 and p[0] < 100 and p[2] < 100]
    assert len(green) > 5, 'no arrow drawn while dragging the goal'


# ------------------------------------------------------------------ meshes

BOX = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
       (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
FACES = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
         (2, 3, 7), (2, 7, 6), (0, 4, 7), (0, 7, 3), (1, 2, 6), (1, 6, 5)]  # outward


def box_dae(half: float, rgba: str) -> str:
    """A Collada cube (Z_UP, metres) with its own material."""
    positions = ' '.join(f'{c * half:g}' for v in BOX for c in v)
    indices = ' '.join(str(i) for f in FACES for i in f)
    return f'''<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_effects><effect id="paint-effect"><profile_COMMON><technique sid="common"><lambert>
    <diffuse><color sid="diffuse">{rgba}</color></diffuse>
  </lambert></technique></profile_COMMON></effect></library_effects>
  <library_materials><material id="paint" name="paint"><instance_effect url="#paint-effect"/>
  </material></library_materials>
  <library_geometries><geometry id="box" name="box"><mesh>
    <source id="box-pos"><float_array id="box-pos-array" count="24">{positions}</float_array>
      <technique_common><accessor source="#box-pos-array" count="8" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="box-vtx"><input semantic="POSITION" source="#box-pos"/></vertices>
    <triangles material="paint" count="12"><input semantic="VERTEX" source="#box-vtx" offset="0"/>
      <p>{indices}</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="scene"><node id="box-node" name="box">
    <instance_geometry url="#box"><bind_material><technique_common>
      <instance_material symbol="paint" target="#paint"/>
    </technique_common></bind_material></instance_geometry>
  </node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
'''


def box_obj(half: float) -> str:
    return ''.join(f'v {x * half:g} {y * half:g} {z * half:g}\n' for x, y, z in BOX) + ''.join(
        f'f {a + 1} {b + 1} {c + 1}\n' for a, b, c in FACES)


def transform(parent: str, child: str, x: float, y: float, stamp: Any) -> Any:
    from geometry_msgs.msg import TransformStamped
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id, t.header.stamp = parent, child, stamp
    t.transform.translation.x, t.transform.translation.y = x, y
    t.transform.rotation.w = 1.0
    return t


def test_dae_and_obj_meshes_and_frame_locked_mesh_markers(ros_env, probe, tmp_path):
    from PIL import Image as PILImage
    from rclpy.qos import DurabilityPolicy, QoSProfile
    from std_msgs.msg import String
    from tf2_msgs.msg import TFMessage
    from visualization_msgs.msg import Marker

    meshes = tmp_path / 'meshes'
    meshes.mkdir()
    (meshes / 'red_box.dae').write_text(box_dae(0.3, '1 0 0 1'))
    (meshes / 'box.obj').write_text(box_obj(0.3))
    urdf = f'''<robot name="meshes">
  <material name="green"><color rgba="0 1 0 1"/></material>
  <link name="base_link"><visual><geometry><mesh filename="file://{meshes}/red_box.dae"/>
  </geometry></visual></link>
  <link name="arm"><visual><geometry><mesh filename="file://{meshes}/box.obj"/></geometry>
    <material name="green"/></visual></link>
  <joint name="j" type="fixed"><parent link="base_link"/><child link="arm"/>
    <origin xyz="0 1.5 0"/></joint>
</robot>'''
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    probe.node.create_publisher(String, '/robot_description', latched).publish(String(data=urdf))
    now = probe.node.get_clock().now().to_msg()
    probe.node.create_publisher(TFMessage, '/tf_static', latched).publish(
        TFMessage(transforms=[transform('base_link', 'arm', 0.0, 1.5, now)]))
    tf = probe.node.create_publisher(TFMessage, '/tf', 10)
    mover = {'x': -2.0}
    probe.node.create_timer(0.05, lambda: tf.publish(TFMessage(transforms=[transform(
        'base_link', 'mover', mover['x'], 0.0, probe.node.get_clock().now().to_msg())])))
    markers = probe.node.create_publisher(Marker, '/visualization_marker', 10)
    config = write_rviz(tmp_path / 'meshes.rviz', 'base_link', [
        display('Grid', 'Grid'), display('RobotModel', 'RobotModel',
                                         **{'Description Topic': {'Value': '/robot_description'}}),
        display('Marker', 'Marker', '/visualization_marker')], TOP_DOWN)
    with rviz_page(ros_env, probe, config, tmp_path) as (_server, page):
        page.wait_for_function(
            '''() => window.rviz && window.rviz.ready && window.rviz.meshes.length === 2
                && window.rviz.status.RobotModel === 'OK' && window.rviz.frames.mover
                && !window.rviz.frames.mover.error''', timeout=40000)
        # The page's Marker subscription is matched: one message of each arrives.
        wait_until(lambda: markers.get_subscription_count() >= 1, 20,
                   "the page's marker subscription")
        for ns, locked, uri, colour, y in (
                ('locked', True, f'file://{meshes}/box.obj', (0.0, 0.0, 1.0), -1.0),
                ('free', False, f'file://{meshes}/red_box.dae', (0.0, 0.0, 0.0), 1.0)):
            m = Marker(ns=ns, id=0, type=Marker.MESH_RESOURCE, action=Marker.ADD,
                       mesh_resource=uri, frame_locked=locked,
                       mesh_use_embedded_materials=not locked)
            m.header.frame_id = 'mover'
            m.pose.position.y, m.pose.orientation.w = y, 1.0
            m.scale.x = m.scale.y = m.scale.z = 1.0
            m.color.r, m.color.g, m.color.b = colour
            m.color.a = 1.0
            markers.publish(m)
        page.wait_for_function('window.rviz.markers.length === 2', timeout=20000)
        page.wait_for_timeout(300)
        before = {m['ns']: m['position'] for m in page.evaluate('window.rviz.markers')}
        at = page.evaluate('''[[0, 0], [0, 1.5], [-2, -1], [-2, 1]].map(([x, y]) =>
            window.rviz.project(x, y, 0.3))''')
        shot = screenshot(page, 'rviz_meshes')
        # mover goes to x = 1: the frame-locked marker follows, the other stays.
        mover['x'] = 1.0
        page.wait_for_function('''() => window.rviz.markers.some((m) => m.ns === 'locked'
            && Math.abs(m.position[0] - 1) < 1e-6)''', timeout=20000)
        after = {m['ns']: m['position'] for m in page.evaluate('window.rviz.markers')}
        status = page.evaluate('window.rviz.status')
        page.wait_for_timeout(100)  # animation frames with the marker moved
        moved_at = page.evaluate('[[1, -1], [-2, -1]].map(([x, y]) => '
                                 'window.rviz.project(x, y, 0.3))')
        moved = screenshot(page, 'rviz_meshes_moved')
    assert status['RobotModel'] == 'OK' and status['Marker'] == 'OK (2 markers)', status
    assert before['locked'] == pytest.approx([-2.0, -1.0, 0.0], abs=1e-6)
    assert before['free'] == pytest.approx([-2.0, 1.0, 0.0], abs=1e-6)
    assert after['locked'] == pytest.approx([1.0, -1.0, 0.0], abs=1e-6)
    assert after['free'] == pytest.approx([-2.0, 1.0, 0.0], abs=1e-6)  # where it was received
    shown = PILImage.open(shot).convert('RGB')

    def dominant(rgb: tuple[int, int, int], channel: int) -> bool:
        return all(rgb[channel] > rgb[i] + 60 for i in range(3) if i != channel)
    # base_link: the DAE's own red; arm: the OBJ in the URDF's green; the markers: the OBJ
    # in the marker's blue, the DAE in its embedded red.
    for (x, y), channel in zip(at, (0, 1, 2, 0), strict=True):
        assert dominant(region(shown, x, y), channel), (x, y, region(shown, x, y))
    # After the move, the blue frame-locked marker is drawn at x = 1, and gone from x = -2.
    shown = PILImage.open(moved).convert('RGB')
    assert dominant(region(shown, *moved_at[0]), 2), region(shown, *moved_at[0])
    assert near(region(shown, *moved_at[1]), (48, 48, 48)), region(shown, *moved_at[1])
