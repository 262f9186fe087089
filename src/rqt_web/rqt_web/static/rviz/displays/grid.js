// Grid: rviz's default, 10 cells of 1 m on the XY plane of the fixed frame.
import * as THREE from 'three';

import {setStatus} from '../panel.js';
import {enabled} from '../state.js';

export function add({scene}) {
  for (const d of enabled('/Grid')) {
    const cells = Number(d.settings?.['Plane Cell Count']) || 10;
    const size = (Number(d.settings?.['Cell Size']) || 1) * cells;
    const grid = new THREE.GridHelper(size, cells, 0xa0a0a4, 0xa0a0a4);
    grid.rotation.x = Math.PI / 2;
    scene.add(grid);
    setStatus(d.name, 'OK');
  }
}
