// Marker and MarkerArray: the markers alive on each display's topic (polled every 100 ms), in
// their frame.
import * as THREE from 'three';

import {note, setStatus} from '../panel.js';
import {place} from '../scene.js';
import {enabled, state} from '../state.js';
import {markerObject, meshErrors} from './marker_shapes.js';

export function add(ctx) {
  const markerDisplays = [...enabled('/Marker'), ...enabled('/MarkerArray')].map((d) => {
    const group = new THREE.Group();
    ctx.scene.add(group);
    ctx.pickable.push(group);
    return {d, group, type: d.class.endsWith('/MarkerArray') ? 'MarkerArray' : 'Marker'};
  });
  // Where a marker's frame was when it came (rviz transforms a marker once, unless it is
  // frame_locked: then it follows its frame). Keyed by display, ns, id; renewed per message.
  const frozen = {};
  const pollMarkers = async () => {
    const drawn = [];
    for (const md of markerDisplays) {
      const data = await rqt.get(`/api/rviz/markers?topic=${encodeURIComponent(md.d.topic || '/visualization_marker')}&type=${md.type}`);
      md.group.clear();
      const problems = [];
      for (const m of data.markers) {
        const key = `${md.d.name}/${m.ns}/${m.id}`;
        let frame = state.frames[m.frame];
        if (!m.frame_locked && frozen[key]?.version === m.version) frame = frozen[key].pose;
        if (!frame || frame.error) {
          problems.push(`No transform from [${m.frame}] to [${state.fixedFrame}]`);
          continue;
        }
        if (!m.frame_locked) frozen[key] = {version: m.version, pose: frame};
        if (m.type === 10 && meshErrors[m.mesh]) {
          problems.push(`Could not load mesh ${m.mesh}: ${meshErrors[m.mesh]}`);
          continue;
        }
        const object = markerObject(m);
        if (!object) {
          problems.push(`marker ${m.ns}/${m.id}: type ${m.type} is not drawn`);
          continue;
        }
        const outer = new THREE.Group();
        place(outer, frame);
        const inner = new THREE.Group();
        inner.position.set(...m.position);
        inner.quaternion.set(...m.orientation);
        inner.add(object);
        outer.add(inner);
        md.group.add(outer);
        outer.updateMatrixWorld(true);
        const at = inner.getWorldPosition(new THREE.Vector3());
        drawn.push({display: md.d.name, ns: m.ns, id: m.id, type: m.type, position: [at.x, at.y, at.z]});
      }
      setStatus(md.d.name, problems.length ? problems[0] : `OK (${data.markers.length} markers)`);
    }
    state.markers = drawn;
  };
  const tickMarkers = async () => {
    try {
      await pollMarkers();
    } catch (error) {
      note.textContent = String(error.message || error);
    }
    setTimeout(tickMarkers, 100);
  };
  if (markerDisplays.length) tickMarkers();
}
