"""tf2_ros: tf2 over ROS 2 topics, with the API of upstream's tf2_ros (Python).

Upstream builds this namespace with star imports (`from tf2_py import *`, `from .buffer
import *`, ...), so it also holds what those modules import: user code relies on some of it,
e.g. `from tf2_ros import TransformBroadcaster, TransformStamped` (the URDF tutorial's
state_publisher.py). The same names are re-exported here, explicitly.
"""
# ruff: noqa: F401 (every import below is a re-export)
import threading
from copy import deepcopy
from threading import Thread
from time import sleep

import builtin_interfaces
import rclpy
import tf2_py as tf2
from geometry_msgs.msg import (
    PointStamped,
    PoseStamped,
    PoseWithCovarianceStamped,
    TransformStamped,
    Vector3Stamped,
)
from rclpy.action import ActionClient
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.clock import Clock, JumpThreshold, TimeJump
from rclpy.duration import Duration
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from rclpy.task import Future
from rclpy.time import Time
from sensor_msgs.msg import PointCloud2
from std_msgs.msg import Header
from tf2_msgs.action import LookupTransform
from tf2_msgs.msg import TFMessage
from tf2_msgs.srv import FrameGraph
from tf2_py import (
    BufferCore,
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)
from tf2_ros.buffer import Buffer
from tf2_ros.buffer_client import BufferClient
from tf2_ros.buffer_interface import (
    BufferInterface,
    ConvertRegistration,
    NotImplementedException,
    Stamped,
    TransformRegistration,
    TypeException,
    convert,
)
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster
from tf2_ros.transform_broadcaster import TransformBroadcaster
from tf2_ros.transform_listener import TransformListener
