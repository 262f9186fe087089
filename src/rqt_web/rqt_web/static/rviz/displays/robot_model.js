// RobotModel: the URDF's visuals, each link placed where tf2 puts its frame.
import * as THREE from 'three';

import {loadMesh, meshInstance} from '../meshes.js';
import {setStatus} from '../panel.js';
import {place} from '../scene.js';
import {enabled, state} from '../state.js';
import {onTf} from '../tf_client.js';

const nums = (text, n) => {
  const values = (text || '').trim().split(/\s+/).filter((s) => s).map(Number);
  return values.length === n && values.every(Number.isFinite) ? values : Array(n).fill(0);
};

// One <visual> of a link, as a group at its <origin> (its mesh added when it has loaded).
const visualObject = (visual, geometry, rgba, alpha, own, link, robotDisplay) => {
  const material = new THREE.MeshLambertMaterial({color: new THREE.Color(rgba[0], rgba[1], rgba[2]),
    transparent: alpha * rgba[3] < 1, opacity: alpha * rgba[3]});
  const holder = new THREE.Group();
  const origin = visual.querySelector(':scope > origin');
  if (origin) {
    holder.position.set(...nums(origin.getAttribute('xyz'), 3));
    const [rr, pp, yy] = nums(origin.getAttribute('rpy'), 3);
    holder.rotation.set(rr, pp, yy, 'ZYX');
  }
  const kind = geometry.nodeName;
  if (kind === 'box') {
    holder.add(new THREE.Mesh(new THREE.BoxGeometry(...nums(geometry.getAttribute('size'), 3)), material));
  } else if (kind === 'cylinder') {
    const radius = Number(geometry.getAttribute('radius')), length = Number(geometry.getAttribute('length'));
    const mesh = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius, length, 32), material);
    mesh.rotation.x = Math.PI / 2;  // three's cylinders run along y, URDF's along z
    holder.add(mesh);
  } else if (kind === 'sphere') {
    holder.add(new THREE.Mesh(new THREE.SphereGeometry(Number(geometry.getAttribute('radius')), 32, 16), material));
  } else if (kind === 'mesh') {
    const uri = geometry.getAttribute('filename') || '';
    const scale = geometry.getAttribute('scale') ? nums(geometry.getAttribute('scale'), 3) : [1, 1, 1];
    // A URDF <material> colours the whole mesh; without one a DAE keeps its own (rviz).
    loadMesh(uri).then((template) => {
      const scaled = new THREE.Group();
      scaled.scale.set(...scale);
      scaled.add(meshInstance(template, material, own));
      holder.add(scaled);
      state.meshes.push({link, uri});
    }, (error) => setStatus(robotDisplay.name, `Could not load mesh ${uri} of link '${link}': ${error.message || error}`));
  }
  return holder;
};

export function add(ctx) {
  const robotDisplay = enabled('/RobotModel')[0];
  const robot = new THREE.Group();
  ctx.scene.add(robot);
  ctx.pickable.push(robot);
  let modelCount = -1;
  const linkGroups = {};
  const buildModel = (xml) => {
    robot.clear();
    for (const key of Object.keys(linkGroups)) delete linkGroups[key];
    const doc = new DOMParser().parseFromString(xml, 'application/xml');
    const root = doc.documentElement;
    if (!root || root.nodeName !== 'robot') {
      setStatus(robotDisplay.name, 'URDF: not a <robot> document');
      return;
    }
    const alpha = Number(robotDisplay.alpha ?? 1);
    const colours = {};
    for (const m of root.querySelectorAll(':scope > material')) {
      const c = m.querySelector('color');
      if (c) colours[m.getAttribute('name')] = nums(c.getAttribute('rgba'), 4);
    }
    const problems = [];
    for (const link of root.querySelectorAll(':scope > link')) {
      const name = link.getAttribute('name');
      const group = new THREE.Group();
      group.visible = false;
      linkGroups[name] = group;
      robot.add(group);
      for (const visual of link.querySelectorAll(':scope > visual')) {
        const geometry = visual.querySelector('geometry > *');
        if (!geometry) continue;
        const mat = visual.querySelector(':scope > material');
        let rgba = [0.8, 0.8, 0.8, 1];
        if (mat) {
          const c = mat.querySelector('color');
          rgba = c ? nums(c.getAttribute('rgba'), 4) : (colours[mat.getAttribute('name')] || rgba);
        }
        group.add(visualObject(visual, geometry, rgba, alpha, !mat, name, robotDisplay));
      }
    }
    setStatus(robotDisplay.name, problems.length ? problems[0] : 'OK');
    state.links = Object.keys(linkGroups);
  };
  // The description topic's latest message, rebuilt when a new one came (polled each second).
  ctx.pollDescription = async () => {
    if (!robotDisplay) return;
    try {
      const d = await rqt.get(`/api/rviz/description?topic=${encodeURIComponent(robotDisplay.topic || '/robot_description')}`);
      if (d.count !== modelCount) {
        modelCount = d.count;
        if (d.urdf) buildModel(d.urdf);
        else setStatus(robotDisplay.name, `No robot description on ${d.topic}`);
      }
    } catch (error) {
      setStatus(robotDisplay.name, String(error.message || error));
    }
  };
  if (!robotDisplay) return;
  onTf((data) => {
    if (!state.links.length) return;
    const missing = [];
    for (const [name, group] of Object.entries(linkGroups)) {
      const pose = data.poses[name];
      if (pose && !pose.error) {
        place(group, pose);
        group.visible = true;
      } else {
        group.visible = false;
        missing.push(name);
      }
    }
    if (missing.length) setStatus(robotDisplay.name, `No transform from [${missing[0]}] to [${data.fixed_frame}]`);
    else if (state.status[robotDisplay.name]?.startsWith('No transform')) setStatus(robotDisplay.name, 'OK');
  });
}
