// Path: a green line through the poses.
import * as THREE from 'three';

export const Path = {type: 'nav_msgs/msg/Path', draw: (holder, msg) => {
  const points = msg.poses.map((p) => new THREE.Vector3(p.pose.position.x, p.pose.position.y, p.pose.position.z));
  holder.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(points),
    new THREE.LineBasicMaterial({color: 0x19ff00})));
}};
