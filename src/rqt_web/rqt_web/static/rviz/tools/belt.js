// The tool belt: the buttons choosing the active tool, and what the tools share: the mouse's
// ray into the scene, its point on the ground plane (the fixed frame's XY plane), and
// publishing through the server. Topics as rviz2's (or the .rviz file's Tools).
import * as THREE from 'three';

import {note, TOOL_NAMES, toolButtons} from '../panel.js';
import {state} from '../state.js';

const TOOL_CLASSES = {initialpose: 'SetInitialPose', goal: 'SetGoal', point: 'PublishPoint'};

// tools: the tool modules' create(ctx, belt), each giving {<tool key>: pointerdown handler}.
export function createBelt(ctx, tools) {
  const {config, controls, renderer, camera} = ctx;
  const toolTopic = (tool) => (config.tools || []).find((t) => t.class.endsWith(`/${TOOL_CLASSES[tool]}`))?.topic;
  const setTool = (tool) => {
    state.tool = tool;
    controls.enabled = tool === 'interact';
    for (const b of toolButtons) b.classList.toggle('active', b.dataset.tool === tool);
  };
  for (const b of toolButtons) b.addEventListener('click', () => setTool(b.dataset.tool));
  const raycaster = new THREE.Raycaster();
  const ground = new THREE.Plane(new THREE.Vector3(0, 0, 1), 0);
  const aim = (event) => {
    const box = renderer.domElement.getBoundingClientRect();
    raycaster.setFromCamera(new THREE.Vector2((event.clientX - box.left) / box.width * 2 - 1,
      1 - (event.clientY - box.top) / box.height * 2), camera);
  };
  const groundPoint = (event) => {
    aim(event);
    return raycaster.ray.intersectPlane(ground, new THREE.Vector3());
  };
  const publish = async (tool, at, yaw) => {
    if (tool === 'nav2goal') {
      // Nav2 Goal sends a navigate_to_pose goal (the Navigation 2 panel shows how it goes).
      await ctx.sendNav2Goal?.(at, yaw);
      return;
    }
    const body = {tool, frame: state.fixedFrame, x: at.x, y: at.y, z: at.z, yaw, topic: toolTopic(tool)};
    try {
      const answer = await rqt.post('/api/rviz/tool', body);
      state.published.push({...body, topic: answer.topic});
      note.textContent = `${TOOL_NAMES[tool]}: published on ${answer.topic}`;
    } catch (error) {
      note.textContent = `${TOOL_NAMES[tool]}: ${error.message || error}`;
    }
  };
  const canvas = renderer.domElement;
  const belt = {canvas, raycaster, aim, groundPoint, publish, setTool};
  const pressHandlers = Object.assign({}, ...tools.map((create) => create(ctx, belt)));
  // Interact leaves the mouse to the camera; the other tools take the left button.
  canvas.addEventListener('pointerdown', (event) => {
    if (state.tool === 'interact' || event.button !== 0) return;
    pressHandlers[state.tool]?.(event);
  });
}
