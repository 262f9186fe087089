// ParticleCloud (nav2_rviz_plugins): amcl's particles as flat arrows in the cloud's frame, each
// as long as its weight says between Min and Max Arrow Length (the heaviest the longest), in
// the display's Color; polled every 200 ms (the server keeps the latest, best effort).
import * as THREE from 'three';

import {note, setStatus} from '../panel.js';
import {place} from '../scene.js';
import {enabled, state} from '../state.js';

const color = (text) => {
  const rgb = String(text || '255; 25; 0').split(';').map((v) => Number(v) / 255);
  return new THREE.Color(rgb[0] || 0, rgb[1] || 0, rgb[2] || 0);
};

// One arrow: shaft along x from the particle, two head strokes back from its tip.
const arrowSegments = (positions, x, y, yaw, length) => {
  const c = Math.cos(yaw), s = Math.sin(yaw);
  const tip = [x + c * length, y + s * length];
  const head = length * 0.3;
  positions.push(x, y, 0, tip[0], tip[1], 0);
  for (const side of [0.5, -0.5]) {
    const a = yaw + Math.PI + side;
    positions.push(tip[0], tip[1], 0, tip[0] + Math.cos(a) * head, tip[1] + Math.sin(a) * head, 0);
  }
};

export function add({scene}) {
  for (const d of enabled('/ParticleCloud')) {
    const settings = d.settings || {};
    const minLength = Number(settings['Min Arrow Length'] ?? 0.02);
    const maxLength = Number(settings['Max Arrow Length'] ?? 0.3);
    const group = new THREE.Group();
    scene.add(group);
    const material = new THREE.LineBasicMaterial({color: color(settings.Color)});
    const info = state.particles[d.name] = {seq: 0, count: 0, frame: null, drawn: 0};
    let lines = null;
    const poll = async () => {
      const data = await rqt.get(`/api/rviz/particles?topic=${encodeURIComponent(d.topic || '/particle_cloud')}`);
      if (!data.frame) {
        setStatus(d.name, `No messages received on ${d.topic}`);
        return;
      }
      const pose = state.frames[data.frame];
      if (!pose || pose.error) {
        setStatus(d.name, `No transform from [${data.frame}] to [${state.fixedFrame}]`);
        return;
      }
      place(group, pose);
      if (data.seq !== info.seq) {
        const heaviest = Math.max(...data.particles.map((p) => p[4]), 1e-12);
        const positions = [];
        for (const [x, y, qz, qw, weight] of data.particles) {
          arrowSegments(positions, x, y, 2 * Math.atan2(qz, qw),
            minLength + (maxLength - minLength) * weight / heaviest);
        }
        if (lines) {
          group.remove(lines);
          lines.geometry.dispose();
        }
        const geometry = new THREE.BufferGeometry();
        geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
        lines = new THREE.LineSegments(geometry, material);
        lines.position.z = 0.05;  // above the map and the costmaps
        group.add(lines);
        Object.assign(info, {seq: data.seq, count: data.particles.length, frame: data.frame,
          drawn: info.drawn + 1});
      }
      setStatus(d.name, 'OK');
    };
    const tick = async () => {
      try {
        await poll();
      } catch (error) {
        note.textContent = String(error.message || error);
      }
      setTimeout(tick, 200);
    };
    tick();
  }
}
