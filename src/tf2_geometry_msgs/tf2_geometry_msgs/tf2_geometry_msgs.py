"""do_transform_* for geometry_msgs types, and their registration with tf2_ros."""
import copy

from geometry_msgs.msg import (
    Point32,
    PointStamped,
    PolygonStamped,
    Pose,
    PoseStamped,
    PoseWithCovarianceStamped,
    TransformStamped,
    Vector3Stamped,
)
from tf2_py.maths import multiply, rotate
from tf2_ros.buffer_interface import ConvertRegistration, TransformRegistration


def _parts(transform: TransformStamped) -> tuple[tuple[float, float, float],
                                                 tuple[float, float, float, float]]:
    t, q = transform.transform.translation, transform.transform.rotation
    return (t.x, t.y, t.z), (q.x, q.y, q.z, q.w)


def _apply(transform: TransformStamped, x: float, y: float,
           z: float) -> tuple[float, float, float]:
    offset, rotation = _parts(transform)
    rx, ry, rz = rotate(rotation, (x, y, z))
    return rx + offset[0], ry + offset[1], rz + offset[2]


def to_msg_msg(msg):
    return msg


def from_msg_msg(msg):
    return msg


def do_transform_point(point: PointStamped, transform: TransformStamped) -> PointStamped:
    """The point, expressed in the transform's frame_id."""
    result = PointStamped()
    result.point.x, result.point.y, result.point.z = _apply(
        transform, point.point.x, point.point.y, point.point.z)
    result.header = transform.header
    return result


def do_transform_vector3(vector3: Vector3Stamped,
                         transform: TransformStamped) -> Vector3Stamped:
    """The vector rotated by the transform (a direction: no translation)."""
    _, rotation = _parts(transform)
    result = Vector3Stamped()
    result.vector.x, result.vector.y, result.vector.z = rotate(
        rotation, (vector3.vector.x, vector3.vector.y, vector3.vector.z))
    result.header = transform.header
    return result


def do_transform_pose(pose: Pose, transform: TransformStamped) -> Pose:
    _, rotation = _parts(transform)
    result = Pose()
    result.position.x, result.position.y, result.position.z = _apply(
        transform, pose.position.x, pose.position.y, pose.position.z)
    o = pose.orientation
    x, y, z, w = multiply(rotation, (o.x, o.y, o.z, o.w))
    if w < 0:
        # q and -q are the same rotation; upstream returns the one with w >= 0 (it goes
        # through a rotation matrix), and so do we: e.g. two half turns give w = +1.
        x, y, z, w = -x, -y, -z, -w
    result.orientation.x, result.orientation.y = x, y
    result.orientation.z, result.orientation.w = z, w
    return result


def do_transform_pose_stamped(pose: PoseStamped, transform: TransformStamped) -> PoseStamped:
    result = PoseStamped()
    result.pose = do_transform_pose(pose.pose, transform)
    result.header = transform.header
    return result


def transform_covariance(cov_in, transform: TransformStamped) -> list[float]:
    """A 6x6 pose covariance (row-major, 36 values) rotated into the transform's frame."""
    _, (x, y, z, w) = _parts(transform)
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    # R6 = diag(R, R); result = R6 * C * R6^T
    big = [[0.0] * 6 for _ in range(6)]
    for i in range(3):
        for j in range(3):
            big[i][j] = big[i + 3][j + 3] = r[i][j]
    cov = [list(cov_in[row * 6:row * 6 + 6]) for row in range(6)]
    left = [[sum(big[i][k] * cov[k][j] for k in range(6)) for j in range(6)] for i in range(6)]
    return [sum(left[i][k] * big[j][k] for k in range(6)) for i in range(6) for j in range(6)]


def do_transform_pose_with_covariance_stamped(
        pose: PoseWithCovarianceStamped,
        transform: TransformStamped) -> PoseWithCovarianceStamped:
    result = PoseWithCovarianceStamped()
    result.pose.pose = do_transform_pose(pose.pose.pose, transform)
    result.pose.covariance = transform_covariance(pose.pose.covariance, transform)
    result.header = transform.header
    return result


def do_transform_polygon_stamped(polygon: PolygonStamped,
                                 transform: TransformStamped) -> PolygonStamped:
    result = copy.deepcopy(polygon)
    result.polygon.points = []
    for point in polygon.polygon.points:
        x, y, z = _apply(transform, point.x, point.y, point.z)
        result.polygon.points.append(Point32(x=x, y=y, z=z))
    result.header = transform.header
    return result


for _type in (Vector3Stamped, PoseStamped, PointStamped):
    ConvertRegistration().add_to_msg(_type, to_msg_msg)
    ConvertRegistration().add_from_msg(_type, from_msg_msg)
for _type, _do_transform in ((PointStamped, do_transform_point),
                             (Vector3Stamped, do_transform_vector3),
                             (PoseStamped, do_transform_pose_stamped),
                             (PoseWithCovarianceStamped,
                              do_transform_pose_with_covariance_stamped),
                             (PolygonStamped, do_transform_polygon_stamped)):
    TransformRegistration().add(_type, _do_transform)
