"""The robot's sensors as ROS messages: lidar (ray casts), IMU (MuJoCo sensors), camera.

Each reads the simulator's current state; stamps are the caller's (sim time). The camera
renders offscreen through EGL: where that cannot start (no EGL/GL libraries, no device) it
says so in one line and the rest of the simulation runs without it.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np
from sensor_msgs.msg import CameraInfo, Image, Imu, LaserScan

EGL_PACKAGES = 'libegl1 libegl-mesa0 libgl1'  # Debian's names for what MUJOCO_GL=egl loads


class Lidar:
    """A planar 360-degree scanner: `samples` rays from angle -pi, counter-clockwise."""

    def __init__(self, model: mujoco.MjModel, body: str, frame_id: str, samples: int,
                 range_min: float, range_max: float, rate: float) -> None:
        self.samples, self.range_min, self.range_max = samples, range_min, range_max
        self.increment = 2 * math.pi / samples
        self.angles = -math.pi + self.increment * np.arange(samples)
        self.local = np.stack([np.cos(self.angles), np.sin(self.angles),
                               np.zeros(samples)], axis=1)
        self.geomid = np.zeros(samples, dtype=np.int32)
        self.dist = np.zeros(samples, dtype=np.float64)
        self.msg = LaserScan()
        self.msg.header.frame_id = frame_id
        self.msg.angle_min = -math.pi
        self.msg.angle_max = -math.pi + self.increment * (samples - 1)
        self.msg.angle_increment = self.increment
        self.msg.scan_time = 1.0 / rate
        self.msg.time_increment = 0.0  # every ray at one instant
        self.msg.range_min, self.msg.range_max = range_min, range_max
        self.bind(model, body)

    def bind(self, model: mujoco.MjModel, body: str) -> None:
        """Look up the sensor's body again (after the model was recompiled)."""
        self.body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, body)
        if self.body < 0:
            raise ValueError(f"lidar frame '{body}' is not a link of the robot")

    def scan(self, model: mujoco.MjModel, data: mujoco.MjData, stamp) -> LaserScan:
        origin = data.xpos[self.body]
        rotation = data.xmat[self.body].reshape(3, 3)
        directions = (self.local @ rotation.T).ravel()
        mujoco.mj_multiRay(model, data, origin, directions, None, True, self.body,
                           self.geomid, self.dist, None, self.samples, self.range_max)
        # mj_multiRay's cutoff only prunes geoms by their bounding spheres: a large geom (a
        # long wall) is still hit beyond it, behind a small one the pruning skipped (a ray
        # read 15.8 m through a pallet at 14.6 m with range_max 12). Beyond range_max the
        # scanner sees nothing, as a real one.
        seen = (self.geomid >= 0) & (self.dist <= self.range_max)
        ranges = np.where(seen, self.dist, np.inf).astype(np.float32)
        ranges[ranges < self.range_min] = -np.inf  # closer than the scanner can see
        self.msg.header.stamp = stamp
        self.msg.ranges = ranges.tolist()
        return self.msg


class ImuSensor:
    """Orientation, angular velocity and linear acceleration (gravity included, as a real
    accelerometer reads it) from MuJoCo's framequat, gyro and accelerometer sensors."""

    def __init__(self, model: mujoco.MjModel, frame_id: str) -> None:
        self.msg = Imu()
        self.msg.header.frame_id = frame_id
        self.bind(model)

    def bind(self, model: mujoco.MjModel) -> None:
        def address(name: str) -> int:
            return int(model.sensor_adr[mujoco.mj_name2id(
                model, mujoco.mjtObj.mjOBJ_SENSOR, name)])
        self.gyro, self.accel = address('imu_gyro'), address('imu_accel')
        self.quat = address('imu_orientation')

    def read(self, data: mujoco.MjData, stamp) -> Imu:
        s = data.sensordata
        m = self.msg
        m.header.stamp = stamp
        m.orientation.w, m.orientation.x, m.orientation.y, m.orientation.z = \
            (float(v) for v in s[self.quat:self.quat + 4])
        (m.angular_velocity.x, m.angular_velocity.y,
         m.angular_velocity.z) = (float(v) for v in s[self.gyro:self.gyro + 3])
        (m.linear_acceleration.x, m.linear_acceleration.y,
         m.linear_acceleration.z) = (float(v) for v in s[self.accel:self.accel + 3])
        return m


class Camera:
    """An RGB camera rendered offscreen (rgb8, `width` x `height`) and its CameraInfo."""

    def __init__(self, model: mujoco.MjModel, frame_id: str, width: int, height: int,
                 fovy_deg: float) -> None:
        self.width, self.height, self.frame_id = width, height, frame_id
        self.renderer: mujoco.Renderer | None = None
        focal = (height / 2) / math.tan(math.radians(fovy_deg) / 2)
        self.info = CameraInfo()
        self.info.header.frame_id = frame_id
        self.info.width, self.info.height = width, height
        self.info.distortion_model = 'plumb_bob'
        self.info.d = [0.0] * 5
        cx, cy = (width - 1) / 2, (height - 1) / 2
        self.info.k = [focal, 0.0, cx, 0.0, focal, cy, 0.0, 0.0, 1.0]
        self.info.r = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
        self.info.p = [focal, 0.0, cx, 0.0, 0.0, focal, cy, 0.0, 0.0, 0.0, 1.0, 0.0]
        self.image = Image()
        self.image.header.frame_id = frame_id
        self.image.width, self.image.height = width, height
        self.image.encoding = 'rgb8'
        self.image.step = 3 * width
        self.bind(model)

    def bind(self, model: mujoco.MjModel) -> None:
        """A renderer for this model (a new one after every recompile). Raises on EGL
        failure: the caller reports it and runs without the camera."""
        if self.renderer is not None:
            self.renderer.close()
            self.renderer = None
        self.renderer = mujoco.Renderer(model, self.height, self.width)

    def capture(self, data: mujoco.MjData, stamp) -> tuple[Image, CameraInfo]:
        renderer = self.renderer
        renderer.update_scene(data, camera='camera')
        flags = renderer.scene.flags
        # Shadows, reflections and the skybox cost 70x the frame time in software GL
        # (768 ms against 11 ms for a 320x240 frame on llvmpipe, measured).
        flags[mujoco.mjtRndFlag.mjRND_SHADOW] = 0
        flags[mujoco.mjtRndFlag.mjRND_REFLECTION] = 0
        flags[mujoco.mjtRndFlag.mjRND_SKYBOX] = 0
        pixels = renderer.render()
        self.image.header.stamp = stamp
        self.image.data = pixels.tobytes()
        self.info.header.stamp = stamp
        return self.image, self.info

    def close(self) -> None:
        if self.renderer is not None:
            self.renderer.close()
            self.renderer = None
