// Interact (rviz2's default tool): the camera, orbiting, panning and zooming with the mouse
// around its focal point (three's OrbitControls), placed as the .rviz file's view says.
import * as THREE from 'three';
import {OrbitControls} from '/vendor/OrbitControls.js';

import {view} from '../panel.js';
import {state} from '../state.js';

export function createCamera(config, renderer) {
  const camera = new THREE.PerspectiveCamera(45, view.clientWidth / view.clientHeight, 0.01, 1000);
  camera.up.set(0, 0, 1);
  const v = config.view || {};
  const distance = Number(v.Distance) || 10, pitch = Number(v.Pitch ?? 0.785), yaw = Number(v.Yaw ?? 0.785);
  camera.position.set(distance * Math.cos(pitch) * Math.cos(yaw), distance * Math.cos(pitch) * Math.sin(yaw),
    distance * Math.sin(pitch));
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.set(0, 0, 0);
  if (String(v.Class || '').endsWith('TopDownOrtho')) {
    // rviz's top-down view: Scale pixels per metre, centred on (X, Y). Seen from straight
    // above at the height where the 45-degree field shows the same metres.
    const scale = Number(v.Scale) || 10, x = Number(v.X) || 0, y = Number(v.Y) || 0;
    const height = (view.clientHeight / scale / 2) / Math.tan(Math.PI / 8);
    camera.position.set(x, y - 0.0001, height);
    controls.target.set(x, y, 0);
  }
  controls.update();
  document.getElementById('rviz-top').addEventListener('click', () => {
    camera.position.set(0, -0.0001, camera.position.length());
    controls.target.set(0, 0, 0);
    controls.update();
  });
  state.camera = camera;
  // Where a point of the fixed frame appears in the page (CSS pixels): for tests and bench.
  state.project = (x, y, z) => {
    const p = new THREE.Vector3(x, y, z).project(camera);
    const box = renderer.domElement.getBoundingClientRect();
    return [box.left + (p.x + 1) / 2 * box.width, box.top + (1 - p.y) / 2 * box.height];
  };
  return {camera, controls};
}
