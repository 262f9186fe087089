// 2D Pose Estimate, 2D Goal Pose and Nav2 Goal: press on the ground plane for the position, drag for the
// orientation (a green arrow shows it), release to publish; then back to Interact, as rviz2.
import * as THREE from 'three';

import {state} from '../state.js';

export function create({scene}, {canvas, groundPoint, publish, setTool}) {
  const toolArrow = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1, 0x19ff00, 0.3, 0.1);
  toolArrow.visible = false;
  scene.add(toolArrow);
  let pressed = null;
  const press = (event) => {
    const at = groundPoint(event);
    if (!at) return;
    pressed = at;
    toolArrow.position.copy(at);
    toolArrow.setDirection(new THREE.Vector3(1, 0, 0));
    toolArrow.visible = true;
    canvas.setPointerCapture(event.pointerId);
  };
  canvas.addEventListener('pointermove', (event) => {
    const at = pressed && groundPoint(event);
    if (at && at.distanceTo(pressed) > 1e-6) toolArrow.setDirection(at.clone().sub(pressed).normalize());
  });
  canvas.addEventListener('pointerup', (event) => {
    if (!pressed) return;
    const at = groundPoint(event);
    const yaw = at && at.distanceTo(pressed) > 1e-6 ? Math.atan2(at.y - pressed.y, at.x - pressed.x) : 0;
    publish(state.tool, new THREE.Vector3(pressed.x, pressed.y, 0), yaw);
    pressed = null;
    toolArrow.visible = false;
    setTool('interact');
  });
  return {initialpose: press, goal: press, nav2goal: press};
}
