"""StaticTransformBroadcaster: latched transforms on /tf_static."""
from collections.abc import Iterable

from geometry_msgs.msg import TransformStamped
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from tf2_msgs.msg import TFMessage

STATIC_BROADCASTER_QOS = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                                    history=HistoryPolicy.KEEP_LAST)


class StaticTransformBroadcaster:
    """Every frame sent so far goes out again in one transient-local message, so a listener
    that joins later receives them all (depth 1 keeps only the latest message)."""

    def __init__(self, node: Node, qos: QoSProfile | int | None = None) -> None:
        self.pub_tf = node.create_publisher(TFMessage, '/tf_static', STATIC_BROADCASTER_QOS
                                            if qos is None else qos)
        self._by_child: dict[str, TransformStamped] = {}

    def sendTransform(self,
                      transform: TransformStamped | Iterable[TransformStamped]) -> None:
        transforms = [transform] if isinstance(transform, TransformStamped) else list(transform)
        for item in transforms:
            self._by_child[item.child_frame_id] = item  # a frame sent again replaces itself
        self.pub_tf.publish(TFMessage(transforms=list(self._by_child.values())))
