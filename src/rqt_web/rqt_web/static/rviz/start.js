// The 3D view, wired: the .rviz config, the renderer and camera, the displays (in the order
// rviz's default plugins are added to the scene), the tools, the TF worker and the render loop.
import * as grid from './displays/grid.js';
import * as image from './displays/image.js';
import * as latest from './displays/latest.js';
import * as map from './displays/map.js';
import * as particleCloud from './displays/particle_cloud.js';
import * as markers from './displays/markers.js';
import * as pointCloud from './displays/point_cloud.js';
import * as robotModel from './displays/robot_model.js';
import * as tf from './displays/tf.js';
import {loadConfig} from './config.js';
import * as nav2Panel from './nav2_panel.js';
import {fixedInput, listDisplays} from './panel.js';
import {installSave} from './save_config.js';
import {createScene} from './scene.js';
import {params, state} from './state.js';
import {drawStreams} from './streams.js';
import {startTf} from './tf_client.js';
import {createBelt} from './tools/belt.js';
import {createCamera} from './tools/interact.js';
import * as poseEstimate from './tools/pose_estimate.js';
import * as publishPoint from './tools/publish_point.js';

// The display registry: each module's add(ctx) draws its class's enabled displays.
const DISPLAYS = [grid, tf, robotModel, markers, latest, pointCloud, image, map, particleCloud];
const TOOLS = [publishPoint, poseEstimate];

export async function start() {
  const config = await loadConfig();
  state.config = config;
  if (!params.get('fixed_frame')) state.fixedFrame = config.fixed_frame;
  fixedInput.value = state.fixedFrame;
  state.displays = config.displays;
  listDisplays(state.displays);
  const {renderer, scene} = createScene(config);
  const {camera, controls} = createCamera(config, renderer);
  installSave(config, camera, controls);
  // pickable: what Publish Point hits (the robot, the markers); pollDescription: RobotModel's.
  const ctx = {config, scene, camera, controls, renderer, pickable: [], pollDescription: null};
  for (const display of DISPLAYS) display.add(ctx);
  nav2Panel.add(ctx);
  createBelt(ctx, TOOLS.map((tool) => tool.create));
  const tfWorker = startTf();
  setInterval(ctx.pollDescription, 1000);
  await ctx.pollDescription();
  const render = () => {
    tfWorker.postMessage(state.fixedFrame);
    drawStreams();
    controls.update();
    renderer.render(scene, camera);
    state.renders += 1;
    requestAnimationFrame(render);
  };
  render();
  state.ready = true;
}
