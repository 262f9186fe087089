"""The simulated world: a world file (MJCF) plus the robot (URDF) plus models spawned at run time.

MuJoCo compiles a whole model at once, so the world is kept as MJCF elements and recompiled
when a model is spawned or deleted; the joints that exist before and after (the robot's free
joint and wheels, other models' joints) keep their positions and velocities, and the clock
goes on. Every failure is a WorldError whose text is one line naming the file or model.
"""

from __future__ import annotations

import copy
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

import mujoco

from mujoco_sim.urdf_to_mjcf import UrdfError, urdf_to_mjcf

WHEEL_KV = 1.0  # N m s/rad: the wheel motors' velocity gain (integrated implicitly)
# N m: the most a wheel motor gives (a stall against a wall). 0.15 N m on a 0.035 m wheel
# pushes 4.3 N, just under the grip of a diffbot wheel (about 5 N at friction 1): at 0.5 N m
# the wheels spun at every start and /odom gained 6 % of the first 3 s' turn (measured).
WHEEL_TORQUE = 0.15
# The driven wheels' contact: the stiffest MuJoCo keeps stable at 2 ms steps (time constant
# 2 x timestep, critically damped). At the default 0.02 s the tyres sank 0.23 mm, the rolling
# radius shrank by 0.66 % and /odom ran ahead of the robot by as much (measured).
WHEEL_SOLREF = '0.004 1'
TIMESTEP = 0.002  # s, unless the world file's <option timestep> says otherwise
SETTLE_STEPS = 250  # 0.5 s with the motors off: the robot comes to rest on its wheels


class WorldError(ValueError):
    """A world, robot or model that cannot be loaded; str() is one line."""


@dataclass(frozen=True)
class RobotSpec:
    urdf: str
    pose: tuple[float, float, float]  # x, y, yaw in the world
    wheels: tuple[str, str]  # left, right joint names
    camera_link: str
    camera_fovy_deg: float
    image_size: tuple[int, int]  # width, height
    imu_link: str


def _one_line(text: str) -> str:
    return ' '.join(str(text).split())


def read_world(path: str) -> ET.Element:
    """The world file's <mujoco> element, or WorldError naming the file and the problem."""
    file = Path(path)
    if not file.is_file():
        raise WorldError(f"world file '{path}' does not exist")
    try:
        root = ET.fromstring(file.read_text())
    except (ET.ParseError, UnicodeDecodeError) as error:
        raise WorldError(f"world file '{path}' is not valid XML: {_one_line(error)}") from None
    if root.tag != 'mujoco':
        raise WorldError(f"world file '{path}' must have a <mujoco> root element, "
                         f'not <{root.tag}>')
    return root


def yaw_quat(yaw: float) -> str:
    return f'{math.cos(yaw / 2):.9g} 0 0 {math.sin(yaw / 2):.9g}'


def pose_attributes(position, orientation) -> dict[str, str]:
    """MJCF pos/quat of a geometry_msgs Pose (quat is w x y z in MJCF)."""
    q = (orientation.w, orientation.x, orientation.y, orientation.z)
    if not any(q):
        q = (1.0, 0.0, 0.0, 0.0)  # an all-zero quaternion (a default Pose) means no rotation
    values = (position.x, position.y, position.z, *q)
    if not all(math.isfinite(v) for v in values):
        raise WorldError('initial_pose must contain finite numbers')
    return {'pos': f'{position.x:.9g} {position.y:.9g} {position.z:.9g}',
            'quat': ' '.join(f'{v:.9g}' for v in q)}


class World:
    """The compiled model and data, and the MJCF they were compiled from."""

    def __init__(self, world_path: str, robot: RobotSpec) -> None:
        self.path = world_path
        self.base = read_world(world_path)
        self.robot = robot
        try:
            self.robot_body, self.skipped = urdf_to_mjcf(robot.urdf)
        except UrdfError as error:
            raise WorldError(f'robot_description: {error}') from None
        self.robot_name = ET.fromstring(robot.urdf).get('name', '')
        x, y, yaw = robot.pose
        self.robot_body.set('pos', f'{x:.9g} {y:.9g} 0')
        self.robot_body.set('quat', yaw_quat(yaw))
        self._add_camera()
        self.spawned: dict[str, ET.Element] = {}
        self.model, self.data = self._compile(self.compose())
        self.robot_start = self._settled_robot()
        self.reset(keep_time=False)

    def _add_camera(self) -> None:
        for body in self.robot_body.iter('body'):
            if body.get('name') == self.robot.camera_link:
                # MuJoCo cameras look along their -z with +y up; the link looks along +x.
                ET.SubElement(body, 'camera', name='camera', xyaxes='0 -1 0 0 0 1',
                              fovy=f'{self.robot.camera_fovy_deg:.9g}')
                return
        raise WorldError(f"camera_frame '{self.robot.camera_link}' is not a link of the robot")

    def body_names(self) -> list[str]:
        """Names of the world file's top-level bodies and the spawned models."""
        world = self.base.find('worldbody')
        names = [b.get('name') for b in world.findall('body')] if world is not None else []
        return [n for n in names if n] + list(self.spawned)

    def compose(self) -> str:
        root = copy.deepcopy(self.base)
        compiler = root.find('compiler')
        if compiler is None:
            compiler = ET.Element('compiler')
            root.insert(0, compiler)
        compiler.set('angle', 'radian')  # the robot's ranges are in radians, as URDF's
        option = root.find('option')
        if option is None:
            option = ET.SubElement(root, 'option')
        option.set('timestep', option.get('timestep', str(TIMESTEP)))
        # Implicit in the wheel motors' velocity gain: stiff motors stay stable at 2 ms.
        option.set('integrator', option.get('integrator', 'implicitfast'))
        option.set('cone', option.get('cone', 'elliptic'))
        option.set('impratio', option.get('impratio', '10'))
        visual = root.find('visual')
        if visual is None:
            visual = ET.SubElement(root, 'visual')
        glob = visual.find('global')
        if glob is None:
            glob = ET.SubElement(visual, 'global')
        width, height = self.robot.image_size
        glob.set('offwidth', str(max(width, int(glob.get('offwidth', '0')))))
        glob.set('offheight', str(max(height, int(glob.get('offheight', '0')))))
        world = root.find('worldbody')
        if world is None:
            world = ET.SubElement(root, 'worldbody')
        robot = copy.deepcopy(self.robot_body)
        for body in robot.iter('body'):
            if any(j.get('name') in self.robot.wheels for j in body.findall('joint')):
                for geom in body.findall('geom'):
                    geom.set('solref', geom.get('solref', WHEEL_SOLREF))
        world.append(robot)
        for body in self.spawned.values():
            world.append(copy.deepcopy(body))
        actuators = ET.SubElement(root, 'actuator')
        for joint in self.robot.wheels:
            ET.SubElement(actuators, 'velocity', name=f'{joint}_motor', joint=joint,
                          kv=str(WHEEL_KV), forcelimited='true',
                          forcerange=f'{-WHEEL_TORQUE} {WHEEL_TORQUE}')
        sensors = ET.SubElement(root, 'sensor')
        site = f'{self.robot.imu_link}_site'
        ET.SubElement(sensors, 'gyro', name='imu_gyro', site=site)
        ET.SubElement(sensors, 'accelerometer', name='imu_accel', site=site)
        ET.SubElement(sensors, 'framequat', name='imu_orientation', objtype='site',
                      objname=site)
        return ET.tostring(root, encoding='unicode')

    def _compile(self, mjcf: str) -> tuple[mujoco.MjModel, mujoco.MjData]:
        try:
            model = mujoco.MjModel.from_xml_string(mjcf)
        except ValueError as error:
            raise WorldError(f"world '{self.path}' with the robot does not compile: "
                             f'{_one_line(error)}') from None
        data = mujoco.MjData(model)
        mujoco.mj_forward(model, data)
        return model, data

    def _recompile(self) -> None:
        """Compile again and carry over the time and every joint that still exists."""
        old_model, old_data = self.model, self.data
        model, data = self._compile(self.compose())
        data.time = old_data.time
        for j in range(old_model.njnt):
            name = mujoco.mj_id2name(old_model, mujoco.mjtObj.mjOBJ_JOINT, j)
            k = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name) if name else -1
            if k < 0:
                continue
            nq = _qpos_size(old_model.jnt_type[j])
            nv = _qvel_size(old_model.jnt_type[j])
            qa, va = old_model.jnt_qposadr[j], old_model.jnt_dofadr[j]
            data.qpos[model.jnt_qposadr[k]:model.jnt_qposadr[k] + nq] = \
                old_data.qpos[qa:qa + nq]
            data.qvel[model.jnt_dofadr[k]:model.jnt_dofadr[k] + nv] = old_data.qvel[va:va + nv]
        data.ctrl[:] = old_data.ctrl[:model.nu]
        mujoco.mj_forward(model, data)
        self.model, self.data = model, data

    def spawn(self, name: str, xml: str, position, orientation) -> None:
        if not name:
            raise WorldError('name must not be empty')
        if name in self.body_names() or name == self.robot_body.get('name'):
            raise WorldError(f"a model named '{name}' already exists")
        body = self._model_body(name, xml)
        body.attrib.update(pose_attributes(position, orientation))
        self.spawned[name] = body
        try:
            self._recompile()
        except WorldError:
            del self.spawned[name]
            raise

    def _model_body(self, name: str, xml: str) -> ET.Element:
        try:
            element = ET.fromstring(xml)
        except ET.ParseError as error:
            raise WorldError(f"model '{name}': xml is not valid XML: {_one_line(error)}") \
                from None
        if element.tag == 'robot':
            try:
                body, _ = urdf_to_mjcf(xml)
            except UrdfError as error:
                raise WorldError(f"model '{name}': {error}") from None
        elif element.tag == 'body':
            body = element
        elif element.tag == 'geom':
            body = ET.Element('body')
            body.append(element)
        else:
            raise WorldError(f"model '{name}': xml must be an MJCF <body> or <geom>, or a "
                             f'URDF <robot>, not <{element.tag}>')
        # Names inside a model are its own: prefixed, two spawned copies do not clash.
        for inner in body.iter():
            if inner is not body and inner.get('name'):
                inner.set('name', f"{name}/{inner.get('name')}")
        body.set('name', name)
        return body

    def delete(self, name: str) -> None:
        if name in self.spawned:
            removed = self.spawned.pop(name)
            try:
                self._recompile()
            except WorldError:
                self.spawned[name] = removed
                raise
            return
        world = self.base.find('worldbody')
        for body in world.findall('body') if world is not None else []:
            if body.get('name') == name:
                world.remove(body)
                try:
                    self._recompile()
                except WorldError:
                    world.append(body)
                    raise
                return
        known = ', '.join(self.body_names()) or 'none'
        raise WorldError(f"no model named '{name}' (models: {known})")

    def _robot_joints(self) -> list[tuple[int, int, int]]:
        """(qpos address, qpos size, joint id) of the robot's free joint and joints."""
        names = [j.get('name') for j in self.robot_body.iter() if j.tag in ('freejoint', 'joint')]
        found = []
        for name in names:
            joint = self.model.joint(name)
            found.append((int(joint.qposadr[0]), _qpos_size(joint.type[0]), joint.id))
        return found

    def _settled_robot(self) -> list[tuple[str, list[float]]]:
        """The robot's joint positions once it rests on its wheels. Started from the URDF's
        pose, the wheels and caster first sink into the ground a little; driving off during
        that landing turned the robot by up to 0.1 rad in 1 m (measured), so every start and
        reset puts the robot down already landed."""
        model, data = self.model, self.data
        for _ in range(SETTLE_STEPS):
            mujoco.mj_step(model, data)
        settled = [(model.joint(j).name, data.qpos[a:a + n].tolist())
                   for a, n, j in self._robot_joints()]
        return settled

    def reset(self, keep_time: bool) -> None:
        """Every joint back to where the world file and the spawn requests put it (the robot
        as it rests at its start)."""
        time = self.data.time
        mujoco.mj_resetData(self.model, self.data)
        for name, values in self.robot_start:
            address = int(self.model.joint(name).qposadr[0])
            self.data.qpos[address:address + len(values)] = values
        if keep_time:
            self.data.time = time
        mujoco.mj_forward(self.model, self.data)


def _qpos_size(joint_type) -> int:
    kind = int(joint_type)  # a numpy integer from the model's arrays
    return 7 if kind == int(mujoco.mjtJoint.mjJNT_FREE) else \
        4 if kind == int(mujoco.mjtJoint.mjJNT_BALL) else 1


def _qvel_size(joint_type) -> int:
    kind = int(joint_type)
    return 6 if kind == int(mujoco.mjtJoint.mjJNT_FREE) else \
        3 if kind == int(mujoco.mjtJoint.mjJNT_BALL) else 1
