// LaserScan: a white point per range within [range_min, range_max].
import * as THREE from 'three';

export const LaserScan = {type: 'sensor_msgs/msg/LaserScan', draw: (holder, msg) => {
  const points = [];
  msg.ranges.forEach((r, i) => {
    if (!(r >= msg.range_min && r <= msg.range_max)) return;
    const a = msg.angle_min + i * msg.angle_increment;
    points.push(new THREE.Vector3(r * Math.cos(a), r * Math.sin(a), 0));
  });
  holder.add(new THREE.Points(new THREE.BufferGeometry().setFromPoints(points),
    new THREE.PointsMaterial({color: 0xffffff, size: 0.05})));
}};
