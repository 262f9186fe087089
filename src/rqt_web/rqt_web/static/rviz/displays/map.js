// Map: the occupancy grid as a texture on a plane in the map's frame, cell (0, 0) at the
// origin's corner and rows along +y, drawn with the display's Alpha (rviz: 0.7) below the robot,
// in its Color Scheme (map; costmap: free cells transparent, as Nav2's costmaps are shown).
// Maps lie just below z = 0 (a path or scan there stays visible), each further Map display
// 5 mm above the one before, so costmaps are drawn over the map.
import * as THREE from 'three';

import {enabled, state} from '../state.js';
import {frameStatus, mapScheme, streamLoop} from '../streams.js';
import {onTf} from '../tf_client.js';

export function add({scene}) {
  for (const [index, d] of enabled('/Map').entries()) {
    const alpha = Number(d.alpha ?? 0.7);
    const scheme = mapScheme(d);
    const see = alpha < 1 || scheme !== 'map';  // rviz blends costmap and raw, not map
    const group = new THREE.Group();
    scene.add(group);
    const info = {received: 0, drawn: 0, width: 0, height: 0, resolution: 0, frame: null, seq: 0, scheme};
    state.maps[d.name] = info;
    let holder = null;
    streamLoop('map', d, (meta, body) => {
      const texture = new THREE.DataTexture(new Uint8Array(body), meta.width, meta.height, THREE.RGBAFormat);
      texture.magFilter = THREE.NearestFilter;
      texture.needsUpdate = true;
      const w = meta.width * meta.resolution, h = meta.height * meta.resolution;
      const plane = new THREE.Mesh(new THREE.PlaneGeometry(w, h), new THREE.MeshBasicMaterial({
        map: texture, side: THREE.DoubleSide, transparent: see, opacity: alpha, depthWrite: !see}));
      plane.position.set(w / 2, h / 2, 0.005 * index - 0.02);
      plane.renderOrder = index;
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
