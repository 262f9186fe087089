// The three.js object of one visualization_msgs/Marker, in the marker's own pose (scale,
// colour, points as the message gives them); null for a type that is not drawn.
import * as THREE from 'three';

import {loadMesh, meshInstance} from '../meshes.js';
import {label} from '../scene.js';

const colour = (c) => new THREE.Color(c[0], c[1], c[2]);
const shapeMaterial = (c) => new THREE.MeshLambertMaterial({color: colour(c), transparent: c[3] < 1, opacity: c[3]});
// Why a MESH_RESOURCE's file could not be drawn, by URI.
export const meshErrors = {};

export const markerObject = (m) => {
  const [sx, sy, sz] = m.scale;
  const pts = m.points.map((p) => new THREE.Vector3(...p));
  switch (m.type) {
    case 0: {  // ARROW: along x, scale = length, width, height
      const dir = new THREE.Vector3(1, 0, 0);
      return new THREE.ArrowHelper(dir, new THREE.Vector3(), sx, colour(m.color), 0.23 * sx, sy);
    }
    case 1: return new THREE.Mesh(new THREE.BoxGeometry(sx, sy, sz), shapeMaterial(m.color));
    case 2: {
      const mesh = new THREE.Mesh(new THREE.SphereGeometry(0.5, 24, 12), shapeMaterial(m.color));
      mesh.scale.set(sx, sy, sz);
      return mesh;
    }
    case 3: {
      const mesh = new THREE.Mesh(new THREE.CylinderGeometry(0.5, 0.5, 1, 24), shapeMaterial(m.color));
      mesh.scale.set(sx, sz, sy);
      mesh.rotation.x = Math.PI / 2;
      const holder = new THREE.Group();
      holder.add(mesh);
      return holder;
    }
    case 4: case 5: {  // LINE_STRIP, LINE_LIST
      const geo = new THREE.BufferGeometry().setFromPoints(pts);
      const mat = new THREE.LineBasicMaterial({color: colour(m.color)});
      return m.type === 4 ? new THREE.Line(geo, mat) : new THREE.LineSegments(geo, mat);
    }
    case 6: case 7: {  // CUBE_LIST, SPHERE_LIST
      const geo = m.type === 6 ? new THREE.BoxGeometry(sx, sy, sz) : new THREE.SphereGeometry(sx / 2, 16, 8);
      const holder = new THREE.Group();
      pts.forEach((p, i) => {
        const mesh = new THREE.Mesh(geo, shapeMaterial(m.colors[i] || m.color));
        mesh.position.copy(p);
        holder.add(mesh);
      });
      return holder;
    }
    case 8: {  // POINTS
      const geo = new THREE.BufferGeometry().setFromPoints(pts);
      return new THREE.Points(geo, new THREE.PointsMaterial({color: colour(m.color), size: sx}));
    }
    case 9: {  // TEXT_VIEW_FACING
      const sprite = label(m.text);
      sprite.scale.set(sz * 5.3, sz, 1);
      sprite.position.set(0, 0, 0);
      return sprite;
    }
    case 10: {  // MESH_RESOURCE: scale multiplies the mesh; its own materials if asked
      const holder = new THREE.Group();
      holder.scale.set(sx, sy, sz);
      loadMesh(m.mesh).then((template) => holder.add(meshInstance(template, shapeMaterial(m.color),
        m.embedded)), (error) => { meshErrors[m.mesh] = String(error.message || error); });
      return holder;
    }
    case 11: {  // TRIANGLE_LIST
      const geo = new THREE.BufferGeometry().setFromPoints(pts);
      geo.computeVertexNormals();
      const mat = shapeMaterial(m.color);
      mat.side = THREE.DoubleSide;
      return new THREE.Mesh(geo, mat);
    }
    default: return null;
  }
};
