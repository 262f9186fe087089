"""A URDF robot as an MJCF <body> tree, so the simulator builds what robot_state_publisher shows.

The tree and its checks are robot_state_publisher's (`urdf_model.parse`): a bad description
is refused here with the same one line. Each link becomes a body placed by its parent joint's
origin; continuous and revolute joints become hinges, prismatic ones slides, fixed joints
weld the child to the parent (a body without a joint). Collision shapes become the colliding
geoms, coloured by the link's first visual material so the camera sees the robot's colours;
<inertial> gives mass and inertia; a link's `<gazebo reference=..><mu1>` its friction.
The root link gets a free joint unless `fixed_base`.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from robot_state_publisher.urdf_model import UrdfError, parse, quaternion_from_rpy

__all__ = ['UrdfError', 'urdf_to_mjcf']


def _fmt(values) -> str:
    return ' '.join(f'{float(v):.9g}' for v in values)


def _quat_wxyz(rpy) -> str:
    x, y, z, w = quaternion_from_rpy(*(float(v) for v in (rpy or (0, 0, 0))))
    return _fmt((w, x, y, z))


def _gazebo_friction(urdf_text: str) -> dict[str, float]:
    """Each link's sliding friction from `<gazebo reference="link"><mu1>`, the tag Gazebo
    robots use (a caster is made slippery that way)."""
    found = {}
    for element in ET.fromstring(urdf_text).findall('gazebo'):
        mu = element.findtext('mu1')
        if element.get('reference') and mu is not None:
            try:
                found[element.get('reference')] = max(0.0, float(mu))
            except ValueError:
                raise UrdfError(f"<gazebo reference=\"{element.get('reference')}\">: mu1 is "
                                f"'{mu}'; allowed: a number >= 0") from None
    return found


def _inertia(i, rpy) -> tuple[float, ...]:
    """The inertia tensor in the link frame (MJCF takes no rotation with fullinertia)."""
    import numpy as np
    tensor = np.array([[i.ixx, i.ixy, i.ixz], [i.ixy, i.iyy, i.iyz], [i.ixz, i.iyz, i.izz]],
                      dtype=float)
    if rpy and any(rpy):
        x, y, z, w = quaternion_from_rpy(*(float(v) for v in rpy))
        rotation = np.array([
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
        tensor = rotation @ tensor @ rotation.T
    return (tensor[0, 0], tensor[1, 1], tensor[2, 2], tensor[0, 1], tensor[0, 2], tensor[1, 2])


def _geom(collision, rgba: str | None, link: str, index: int) -> ET.Element | None:
    from urdf_parser_py import urdf
    shape = collision.geometry
    geom = ET.Element('geom', name=f'{link}_collision_{index}')
    if isinstance(shape, urdf.Box):
        geom.set('type', 'box')
        geom.set('size', _fmt(s / 2 for s in shape.size))
    elif isinstance(shape, urdf.Cylinder):
        geom.set('type', 'cylinder')
        geom.set('size', _fmt((shape.radius, shape.length / 2)))
    elif isinstance(shape, urdf.Sphere):
        geom.set('type', 'sphere')
        geom.set('size', _fmt((shape.radius,)))
    else:
        return None  # meshes: not simulated (the caller reports them)
    origin = collision.origin
    if origin is not None:
        geom.set('pos', _fmt(origin.xyz or (0, 0, 0)))
        geom.set('quat', _quat_wxyz(origin.rpy))
    if rgba:
        geom.set('rgba', rgba)
    return geom


def urdf_to_mjcf(urdf_text: str, fixed_base: bool = False) -> tuple[ET.Element, list[str]]:
    """The robot's root <body> and the list of collision shapes that were left out (meshes).

    Raises UrdfError with one line when the description is not a usable URDF.
    """
    from urdf_parser_py import urdf
    model = parse(urdf_text)  # validates the tree with robot_state_publisher's messages
    robot = urdf.URDF.from_xml_string(urdf_text.encode())
    materials = {m.name: m for m in robot.materials if m.color is not None}
    links = {link.name: link for link in robot.links}
    friction = _gazebo_friction(urdf_text)
    skipped: list[str] = []

    def body_for(name: str) -> ET.Element:
        body = ET.Element('body', name=name)
        link = links[name]
        rgba = None
        for visual in link.visuals:
            material = visual.material
            if material is not None:
                color = material.color or (materials[material.name].color
                                           if material.name in materials else None)
                if color is not None:
                    rgba = _fmt(color.rgba)
                    break
        if link.inertial is not None and link.inertial.mass:
            inertial = link.inertial
            origin = inertial.origin
            element = ET.SubElement(body, 'inertial', mass=f'{float(inertial.mass):.9g}')
            element.set('fullinertia', _fmt(_inertia(inertial.inertia,
                                                     origin.rpy if origin else None)))
            element.set('pos', _fmt(origin.xyz if origin and origin.xyz else (0, 0, 0)))
        for index, collision in enumerate(link.collisions):
            geom = _geom(collision, rgba, name, index)
            if geom is None:
                skipped.append(f'{name} (mesh)')
                continue
            if name in friction:
                # MuJoCo takes the larger friction of two geoms unless one has priority.
                geom.set('friction', f'{friction[name]:.9g} 0.005 0.0001')
                geom.set('priority', '1')
            body.append(geom)
        # A site at the link's origin: sensors (IMU) and frames are read from it.
        ET.SubElement(body, 'site', name=f'{name}_site', size='0.005')
        return body

    bodies = {model.root: body_for(model.root)}
    if not fixed_base:
        bodies[model.root].insert(0, ET.Element('freejoint', name=f'{model.root}_freejoint'))
    for joint in model.joints:  # parents before children
        child = body_for(joint.child)
        child.set('pos', _fmt(joint.xyz))
        x, y, z, w = joint.rotation
        child.set('quat', _fmt((w, x, y, z)))
        if joint.type in ('continuous', 'revolute', 'prismatic'):
            element = ET.Element('joint', name=joint.name, axis=_fmt(joint.axis),
                                 type='slide' if joint.type == 'prismatic' else 'hinge')
            if joint.type != 'continuous':
                element.set('range', _fmt((joint.lower, joint.upper)))
                element.set('limited', 'true')
            child.insert(0, element)
        bodies[joint.parent].append(child)
        bodies[joint.child] = child
    return bodies[model.root], skipped
