// TF: each frame's axes and name where tf2 puts it, and a line to its parent.
import * as THREE from 'three';

import {setStatus} from '../panel.js';
import {label, place} from '../scene.js';
import {enabled} from '../state.js';
import {onTf} from '../tf_client.js';

export function add({scene}) {
  const tfDisplay = enabled('/TF')[0];
  const tfGroup = new THREE.Group();
  scene.add(tfGroup);
  const tfObjects = {};
  const tfFrame = (name) => {
    if (!tfObjects[name]) {
      const group = new THREE.Group();
      const scale = Number(tfDisplay?.settings?.['Marker Scale']) || 1;
      const axes = new THREE.AxesHelper(0.25 * scale);
      group.add(axes, label(name));
      tfGroup.add(group);
      tfObjects[name] = {group};
    }
    return tfObjects[name];
  };
  // Every frame's line to its parent, as segments of one object: one draw and one upload per
  // TF answer (a Line per frame was 107 of each, 43 -> 60 frames/s in software rendering).
  const tfLines = new THREE.LineSegments(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({color: 0xff66cc}));
  tfLines.frustumCulled = false;  // its extent changes with every answer
  tfGroup.add(tfLines);
  const setTfLines = (ends) => {
    let position = tfLines.geometry.getAttribute('position');
    if (!position || position.array.length < ends.length) {
      position = new THREE.BufferAttribute(new Float32Array(Math.max(ends.length, 64) * 2), 3);
      position.setUsage(THREE.DynamicDrawUsage);
      tfLines.geometry.setAttribute('position', position);
    }
    position.array.set(ends);
    position.needsUpdate = true;
    tfLines.geometry.setDrawRange(0, ends.length / 3);
  };
  if (!tfDisplay) return;
  onTf((data) => {
    const fixed = data.fixed_frame;
    for (const [name, pose] of Object.entries(data.poses)) {
      if (!pose.error) {
        const item = tfFrame(name);
        place(item.group, pose);
        item.group.visible = true;
      } else if (tfObjects[name]) {
        tfObjects[name].group.visible = false;
      }
    }
    const ends = [];
    for (const [child, parent] of Object.entries(data.parents)) {
      const c = data.poses[child], p = data.poses[parent];
      if (c && p && !c.error && !p.error) ends.push(...c.translation, ...p.translation);
    }
    setTfLines(ends);
    const names = Object.keys(data.poses).filter((n) => n !== fixed);
    setStatus(tfDisplay.name, names.length || data.poses[fixed] && !data.poses[fixed].error ? 'OK'
      : `Fixed Frame [${fixed}] does not exist`);
  });
}
