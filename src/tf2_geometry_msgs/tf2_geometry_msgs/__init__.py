"""tf2_geometry_msgs: transform geometry_msgs types with a TransformStamped.

Importing it registers the stamped types with tf2_ros' Buffer.transform(), as upstream.
"""
from tf2_geometry_msgs.tf2_geometry_msgs import (  # noqa: F401
    do_transform_point,
    do_transform_polygon_stamped,
    do_transform_pose,
    do_transform_pose_stamped,
    do_transform_pose_with_covariance_stamped,
    do_transform_vector3,
    from_msg_msg,
    to_msg_msg,
    transform_covariance,
)
