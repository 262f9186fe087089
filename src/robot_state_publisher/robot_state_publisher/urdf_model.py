"""A URDF as a tree of joints, and each joint's transform for a position.

Parsing is urdfdom_py's (`urdf_parser_py`, the parser ROS ships for Python); on top of it we
check the tree as urdfdom's C++ `initTree` does (every joint names existing links, each link
has one parent, one root, no loop), so a bad file is refused with one line naming the element.
Joint motion follows KDL as upstream uses it: the joint origin, then a rotation about (or a
translation along) the joint axis; planar joints count as fixed and floating joints are
skipped, as kdl_parser and robot_state_publisher do.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

Vector = tuple[float, float, float]
Quaternion = tuple[float, float, float, float]  # x, y, z, w

MOVING_TYPES = ('revolute', 'continuous', 'prismatic')
JOINT_TYPES = ('revolute', 'continuous', 'prismatic', 'fixed', 'floating', 'planar')


class UrdfError(ValueError):
    """A robot description that cannot be used; str() is one line naming the element."""


@dataclass(frozen=True)
class Mimic:
    joint: str
    multiplier: float
    offset: float


@dataclass(frozen=True)
class Joint:
    name: str
    type: str
    parent: str
    child: str
    xyz: Vector
    rotation: Quaternion
    axis: Vector
    lower: float
    upper: float
    mimic: Mimic | None

    def transform(self, position: float = 0.0) -> tuple[Vector, Quaternion]:
        """Pose of the child link in the parent link at this joint position."""
        if self.type in ('revolute', 'continuous'):
            return self.xyz, multiply(self.rotation, axis_angle(self.axis, position))
        if self.type == 'prismatic':
            offset = rotate(self.rotation, tuple(a * position for a in self.axis))
            return (self.xyz[0] + offset[0], self.xyz[1] + offset[1],
                    self.xyz[2] + offset[2]), self.rotation
        return self.xyz, self.rotation


@dataclass(frozen=True)
class RobotModel:
    name: str
    root: str
    links: tuple[str, ...]
    joints: tuple[Joint, ...]  # in tree order, parents before children
    meshes: tuple[tuple[str, str], ...] = ()  # (link, filename) of each visual/collision mesh

    def moving(self) -> dict[str, Joint]:
        return {j.name: j for j in self.joints if j.type in MOVING_TYPES}

    def fixed(self) -> list[Joint]:
        return [j for j in self.joints if j.type in ('fixed', 'planar')]


def quaternion_from_rpy(roll: float, pitch: float, yaw: float) -> Quaternion:
    """URDF's rpy: fixed-axis roll about x, then pitch about y, then yaw about z."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def axis_angle(axis: Vector, angle: float) -> Quaternion:
    s = math.sin(angle / 2)
    return (axis[0] * s, axis[1] * s, axis[2] * s, math.cos(angle / 2))


def multiply(a: Quaternion, b: Quaternion) -> Quaternion:
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


def rotate(q: Quaternion, v: Vector) -> Vector:
    x, y, z, _w = multiply(multiply(q, (v[0], v[1], v[2], 0.0)), (-q[0], -q[1], -q[2], q[3]))
    return (x, y, z)


def _one_line(error: Exception) -> str:
    return ' '.join(str(error).split())


def parse(xml: str) -> RobotModel:
    """The robot in `xml`, or UrdfError naming what is wrong."""
    if not xml.strip():
        raise UrdfError('robot_description parameter must not be empty')
    from lxml import etree
    from urdf_parser_py import urdf
    data = xml.encode() if isinstance(xml, str) else xml
    try:
        _check_joint_types(etree.fromstring(data))
        robot = urdf.URDF.from_xml_string(data)
    except etree.XMLSyntaxError as error:
        where = _one_line(error).replace(' (<string>, line 1)', '')
        raise UrdfError(f'robot description is not valid XML: {where}') from None
    except UrdfError:
        raise
    except Exception as error:  # urdf_parser_py raises ParseError, AssertionError, ...
        raise UrdfError(f'robot description is not a valid URDF: {_one_line(error)}') from None
    return _build(robot)


def _check_joint_types(root) -> None:
    """urdfdom's wording for a joint without a type or of an unknown one (urdf_parser_py's
    is a ParseError with an XPath)."""
    for element in root.iter('joint'):
        if element.getparent() is not root:  # <joint> inside <transmission> is a reference
            continue
        name, kind = element.get('name'), element.get('type')
        if kind is None:
            raise UrdfError(f"joint [{name}] has no type, check to see if it's a reference.")
        if kind not in JOINT_TYPES:
            raise UrdfError(f'Joint [{name}] has no known type [{kind}] '
                            f'(allowed: {", ".join(JOINT_TYPES)})')


def _meshes(robot) -> tuple[tuple[str, str], ...]:
    found = []
    for link in robot.links:
        for element in [*link.visuals, *link.collisions]:
            geometry = getattr(element, 'geometry', None)
            filename = getattr(geometry, 'filename', None)
            if filename and (link.name, filename) not in found:
                found.append((link.name, filename))
    return tuple(found)


def mesh_path(uri: str) -> str | None:
    """Local path of a mesh `filename` (package://, file:// or a plain path), or None if
    the package is unknown or the scheme is not a local one."""
    if uri.startswith('package://'):
        package, _, relative = uri[len('package://'):].partition('/')
        from ament_index_python.packages import (
            PackageNotFoundError,
            get_package_share_directory,
        )
        try:
            return f'{get_package_share_directory(package)}/{relative}'
        except PackageNotFoundError:
            return None
    if uri.startswith('file://'):
        return uri[len('file://'):]
    if '://' in uri:
        return None
    return uri


def missing_meshes(model: RobotModel) -> list[str]:
    """One line per mesh file of the model that is not on this machine."""
    import os
    lines = []
    for link, uri in model.meshes:
        path = mesh_path(uri)
        if path is None and uri.startswith('package://'):
            package = uri[len('package://'):].partition('/')[0]
            lines.append(f"link '{link}': mesh [{uri}] not found: package [{package}] "
                         'not found')
        elif path is not None and not os.path.isfile(path):
            lines.append(f"link '{link}': mesh [{uri}] not found: no file {path}")
    return lines


def _build(robot) -> RobotModel:
    links = [link.name for link in robot.links]
    seen: set[str] = set()
    for name in links:
        if name in seen:
            raise UrdfError(f"link '{name}' is not unique")
        seen.add(name)
    if not links:
        raise UrdfError(f"robot '{robot.name}' has no <link>")
    parent_of: dict[str, str] = {}
    joints: dict[str, Joint] = {}
    for j in robot.joints:
        where = f"joint '{j.name}'"
        if j.name in joints:
            raise UrdfError(f'{where} is not unique')
        for role, link in (('child', j.child), ('parent', j.parent)):
            if link not in seen:  # urdfdom's wording
                raise UrdfError(f'{role} link [{link}] of joint [{j.name}] not found')
        if j.child in parent_of:
            raise UrdfError(f'{where}: child link [{j.child}] already has a parent '
                            f'(joint \'{parent_of[j.child]}\')')
        parent_of[j.child] = j.name
        joints[j.name] = _joint(j, where)
    roots = [name for name in links if name not in parent_of]
    if not roots:
        raise UrdfError('No root link found. The robot xml is not a valid tree.')
    if len(roots) > 1:
        raise UrdfError(f'Two root links found: [{roots[0]}] and [{roots[1]}]')
    children: dict[str, list[Joint]] = {}
    for joint in joints.values():
        children.setdefault(joint.parent, []).append(joint)
    ordered: list[Joint] = []
    stack = [roots[0]]
    while stack:
        for joint in children.get(stack.pop(), []):
            ordered.append(joint)
            stack.append(joint.child)
    if len(ordered) != len(joints):  # a cycle not reachable from the root
        lost = sorted(set(joints) - {j.name for j in ordered})
        raise UrdfError(f"joint '{lost[0]}' is in a loop not connected to root link "
                        f'[{roots[0]}]')
    for joint in ordered:
        if joint.mimic and joint.mimic.joint not in joints:
            raise UrdfError(f"joint '{joint.name}': mimic joint [{joint.mimic.joint}] "
                            'not found')
    return RobotModel(robot.name, roots[0], tuple(links), tuple(ordered), _meshes(robot))


def _joint(j, where: str) -> Joint:
    origin = j.origin
    xyz = tuple(float(v) for v in (origin.xyz if origin and origin.xyz else (0, 0, 0)))
    rpy = tuple(float(v) for v in (origin.rpy if origin and origin.rpy else (0, 0, 0)))
    axis = tuple(float(v) for v in (j.axis if j.axis is not None else (1, 0, 0)))
    if not all(math.isfinite(v) for v in (*xyz, *rpy, *axis)):
        raise UrdfError(f'{where}: origin and axis must be finite numbers')
    norm = math.sqrt(sum(a * a for a in axis))
    if j.type in MOVING_TYPES and norm == 0.0:
        raise UrdfError(f'{where}: axis must not be zero')
    axis = tuple(a / norm for a in axis) if norm else axis
    limit = j.limit
    lower = float(limit.lower) if limit is not None and limit.lower is not None else 0.0
    upper = float(limit.upper) if limit is not None and limit.upper is not None else 0.0
    if j.type in ('revolute', 'prismatic') and limit is None:
        raise UrdfError(f'{where}: a {j.type} joint needs a <limit>')
    mimic = None
    if j.mimic is not None:
        mimic = Mimic(j.mimic.joint, float(j.mimic.multiplier if j.mimic.multiplier
                                           is not None else 1.0),
                      float(j.mimic.offset if j.mimic.offset is not None else 0.0))
    return Joint(j.name, j.type, j.parent, j.child, xyz, quaternion_from_rpy(*rpy), axis,
                 lower, upper, mimic)
