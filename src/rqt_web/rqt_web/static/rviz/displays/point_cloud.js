// PointCloud2: THREE.Points of the finite points, coloured as the server's RGB8 or Intensity
// transformer gave them (or the display's FlatColor); Size (m) as flat squares, Style Points
// as Size (Pixels).
import * as THREE from 'three';

import {enabled, state} from '../state.js';
import {frameStatus, streamLoop} from '../streams.js';
import {onTf} from '../tf_client.js';

export function add({scene}) {
  for (const d of enabled('/PointCloud2')) {
    const s = d.settings || {};
    const pixels = s.Style === 'Points';
    const size = pixels ? Number(s['Size (Pixels)']) || 3 : Number(s['Size (m)']) || 0.01;
    const flat = s['Color Transformer'] === 'FlatColor';
    const flatColour = new THREE.Color(...String(s.Color || '255; 255; 255').split(';').map((v) => Number(v) / 255));
    const alpha = Number(d.alpha ?? 1);
    const group = new THREE.Group();
    scene.add(group);
    const info = {received: 0, drawn: 0, points: 0, frame: null, seq: 0, color: null};
    state.clouds[d.name] = info;
    let points = null;
    streamLoop('cloud', d, (meta, body) => {
      const geo = new THREE.BufferGeometry();
      geo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(body, 0, meta.points * 3), 3));
      const coloured = Boolean(meta.color) && !flat;
      if (coloured) {
        geo.setAttribute('color', new THREE.BufferAttribute(new Uint8Array(body, meta.points * 12, meta.points * 3), 3, true));
      }
      const material = new THREE.PointsMaterial({size, sizeAttenuation: !pixels, vertexColors: coloured,
        color: coloured ? 0xffffff : flatColour, transparent: alpha < 1, opacity: alpha});
      if (points) {
        group.remove(points);
        points.geometry.dispose();
        points.material.dispose();
      }
      points = new THREE.Points(geo, material);
      points.frustumCulled = false;  // no bounding sphere over every point of every cloud
      group.add(points);
      Object.assign(info, {drawn: info.drawn + 1, points: meta.points, frame: meta.frame,
        seq: meta.seq, color: meta.color});
      frameStatus(d, group, meta.frame);
    }, info);
    onTf(() => { if (info.frame !== null) frameStatus(d, group, info.frame); });
  }
}
