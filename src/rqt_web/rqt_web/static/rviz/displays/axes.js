// Axes: a frame's axes (Reference Frame, or the fixed frame), placed at each poll of the
// message displays (latest.js).
import * as THREE from 'three';

import {setStatus} from '../panel.js';
import {place} from '../scene.js';
import {enabled, state} from '../state.js';

// The Axes displays' objects; update() moves each to its frame and sets its status.
export function addAxes({scene}) {
  return enabled('/Axes').map((d) => {
    const length = Number(d.settings?.Length) || 1;
    const axes = new THREE.AxesHelper(length);
    scene.add(axes);
    const reference = d.settings?.['Reference Frame'] || '<Fixed Frame>';
    return {update: () => {
      const frame = reference === '<Fixed Frame>' ? state.fixedFrame : reference;
      const pose = state.frames[frame];
      axes.visible = Boolean(pose && !pose.error);
      if (axes.visible) place(axes, pose);
      setStatus(d.name, axes.visible ? 'OK' : `No transform from [${frame}] to [${state.fixedFrame}]`);
    }};
  });
}
