// Mesh files, loaded once per URI: STL, DAE (three's ColladaLoader) and OBJ (OBJLoader), for
// the RobotModel and MESH_RESOURCE markers. Collada's up_axis is ignored as rviz does (assimp's
// IGNORE_UP_DIRECTION): three turns Z_UP files to Y up, undone here; the unit scale is kept. A
// DAE's textures are fetched next to it (resolved against its package:// or file:// URI).
import * as THREE from 'three';
import {STLLoader} from '/vendor/STLLoader.js';

const stl = new STLLoader();
const resourceUrl = (uri) => `/api/rviz/resource?uri=${encodeURIComponent(uri)}`;
const meshCache = {};

export const loadMesh = (uri) => {
  meshCache[uri] ??= (async () => {
    const url = resourceUrl(uri);
    const ext = uri.toLowerCase().split('.').pop();
    if (ext === 'stl') return new THREE.Mesh(await stl.loadAsync(url), new THREE.MeshLambertMaterial());
    if (ext === 'dae') {
      const {ColladaLoader} = await import('/vendor/addons/loaders/ColladaLoader.js');
      const manager = new THREE.LoadingManager();
      const base = uri.slice(0, uri.lastIndexOf('/') + 1);
      manager.setURLModifier((u) => (u.startsWith('/api/rviz/') && !u.startsWith('/api/rviz/resource?')
        ? resourceUrl(base + u.slice('/api/rviz/'.length)) : u));
      const dae = await new ColladaLoader(manager).loadAsync(url);
      dae.scene.rotation.set(0, 0, 0);
      dae.scene.userData.embedded = true;  // the file's own materials
      return dae.scene;
    }
    if (ext === 'obj') {
      const {OBJLoader} = await import('/vendor/addons/loaders/OBJLoader.js');
      return new OBJLoader().loadAsync(url);
    }
    throw new Error('only STL, DAE and OBJ meshes are drawn');
  })();
  return meshCache[uri];
};

// A copy of a loaded mesh in `material`, or in its own materials when `own` and it has them.
export const meshInstance = (template, material, own) => {
  const copy = template.clone(true);
  if (!(own && template.userData.embedded)) copy.traverse((o) => { if (o.isMesh) o.material = material; });
  return copy;
};
