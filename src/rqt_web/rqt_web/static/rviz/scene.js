// The renderer, the scene and its lights, and the three.js helpers the displays share.
import * as THREE from 'three';

import {view} from './panel.js';
import {state} from './state.js';

// Whether WebGL runs in software (no GPU: SwiftShader, llvmpipe).
const softwareRenderer = () => {
  const gl = document.createElement('canvas').getContext('webgl2') || document.createElement('canvas').getContext('webgl');
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /SwiftShader|llvmpipe|softpipe|software/i.test(name);
};

export function createScene(config) {
  // Colours as given (rviz's 0-255 background, URDF rgba), without sRGB conversion.
  THREE.ColorManagement.enabled = false;
  // Multisampling off when point clouds are shown: it does nothing for points and cost 2.4x
  // per frame with 100,000 of them in Chromium's software renderer (7 -> 17 frames/s).
  const clouds = state.displays.some((d) => d.enabled && d.class.endsWith('/PointCloud2'));
  // Off in a software renderer too, where 4 samples a pixel are 4 times the fragment work on
  // the CPU: with r2d2 and 107 TF frames, 34 -> 48 frames/s and the /joint_states-to-screen
  // lag 55 -> 38 ms (p50), the CPU shared with ROS here.
  const software = softwareRenderer();
  state.antialias = !clouds && !software;
  const renderer = new THREE.WebGLRenderer({antialias: state.antialias, preserveDrawingBuffer: true});
  renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
  renderer.setSize(view.clientWidth, view.clientHeight);
  const [r, g, b] = config.background;
  renderer.setClearColor(new THREE.Color(r / 255, g / 255, b / 255));
  view.append(renderer.domElement);
  const scene = new THREE.Scene();
  scene.add(new THREE.AmbientLight(0xffffff, 0.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(3, 2, 6);
  scene.add(sun);
  return {renderer, scene};
}

// An object moved to a tf2 pose (translation, rotation as x, y, z, w) of the fixed frame.
export const place = (object, pose) => {
  object.position.set(...pose.translation);
  object.quaternion.set(...pose.rotation);
};

// A text sprite, facing the camera: TF frame names and TEXT_VIEW_FACING markers.
export const label = (text) => {
  const canvas = document.createElement('canvas');
  canvas.width = 256; canvas.height = 48;
  const ctx = canvas.getContext('2d');
  ctx.font = '28px sans-serif'; ctx.fillStyle = '#ffffff'; ctx.fillText(text, 4, 34);
  const sprite = new THREE.Sprite(new THREE.SpriteMaterial({map: new THREE.CanvasTexture(canvas), depthTest: false}));
  sprite.scale.set(0.5, 0.094, 1);
  sprite.position.set(0, 0, 0.08);
  return sprite;
};
