// Map: the occupancy grid as a texture on a plane in the map's frame, cell (0, 0) at the
// origin's corner and rows along +y, drawn with the display's Alpha (rviz: 0.7) below the robot.
import * as THREE from 'three';

import {enabled, state} from '../state.js';
import {frameStatus, streamLoop} from '../streams.js';
import {onTf} from '../tf_client.js';

export function add({scene}) {
  for (const d of enabled('/Map')) {
    const alpha = Number(d.alpha ?? 0.7);
    const group = new THREE.Group();
    scene.add(group);
    const info = {received: 0, drawn: 0, width: 0, height: 0, resolution: 0, frame: null, seq: 0};
    state.maps[d.name] = info;
    let holder = null;
    streamLoop('map', d, (meta, body) => {
      const texture = new THREE.DataTexture(new Uint8Array(body), meta.width, meta.height, THREE.RGBAFormat);
      texture.magFilter = THREE.NearestFilter;
      texture.needsUpdate = true;
      const w = meta.width * meta.resolution, h = meta.height * meta.resolution;
      const plane = new THREE.Mesh(new THREE.PlaneGeometry(w, h), new THREE.MeshBasicMaterial({
        map: texture, side: THREE.DoubleSide, transparent: alpha < 1, opacity: alpha, depthWrite: alpha >= 1}));
      plane.position.set(w / 2, h / 2, 0);
      if (holder) {
        group.remove(holder);
        holder.children[0].geometry.dispose();
        holder.children[0].material.map.dispose();
        holder.children[0].material.dispose();
      }
      holder = new THREE.Group();
      holder.position.set(...meta.position);
      holder.quaternion.set(...meta.orientation);
      holder.add(plane);
      group.add(holder);
      Object.assign(info, {drawn: info.drawn + 1, width: meta.width, height: meta.height,
        resolution: meta.resolution, frame: meta.frame, seq: meta.seq});
      frameStatus(d, group, meta.frame);
    }, info);
    onTf(() => { if (info.frame !== null) frameStatus(d, group, info.frame); });
  }
}
