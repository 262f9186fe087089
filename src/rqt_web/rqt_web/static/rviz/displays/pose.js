// Pose, PoseArray and Odometry: a red arrow along each pose's x axis.
import * as THREE from 'three';

const arrow = (pose, hex) => {
  const o = new THREE.Group();
  o.position.set(pose.position.x, pose.position.y, pose.position.z);
  const q = pose.orientation;
  o.quaternion.set(q.x, q.y, q.z, q.w);
  o.add(new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1, hex, 0.3, 0.1));
  return o;
};

// Each display class: its message type, and what draws a message into `holder`.
export const Pose = {type: 'geometry_msgs/msg/PoseStamped',
  draw: (holder, msg) => { holder.add(arrow(msg.pose, 0xff1919)); }};
export const PoseArray = {type: 'geometry_msgs/msg/PoseArray',
  draw: (holder, msg) => { for (const pose of msg.poses) holder.add(arrow(pose, 0xff1919)); }};
export const Odometry = {type: 'nav_msgs/msg/Odometry',
  draw: (holder, msg) => { holder.add(arrow(msg.pose.pose, 0xff1919)); }};
