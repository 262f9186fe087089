// The page around the 3D view: Fixed Frame box, view and save buttons, the tool belt, the
// display list with each display's status, the view itself and the image panels.
import {state} from './state.js';

const main = document.getElementById('main');

export const fixedInput = rqt.el('input', {id: 'rviz-fixed-frame', value: state.fixedFrame, size: 16});
const list = rqt.el('ul', {id: 'rviz-displays'});
export const note = rqt.el('span', {id: 'rviz-note', class: 'keys'});
export const view = rqt.el('div', {id: 'rviz-view', style: 'width:100%;height:560px;position:relative'});
// The tool belt: rviz2's default tools (Interact moves the camera).
// Nav2 Goal (nav2_rviz_plugins/GoalTool) shows only with a config that names it.
export const TOOL_NAMES = {interact: 'Interact', initialpose: '2D Pose Estimate', goal: '2D Goal Pose',
  nav2goal: 'Nav2 Goal', point: 'Publish Point'};
export const toolButtons = Object.entries(TOOL_NAMES).map(([key, text]) =>
  rqt.el('button', {id: `rviz-tool-${key}`, 'data-tool': key, text, class: key === 'interact' ? 'active' : ''}));
export const imagePanel = rqt.el('div', {id: 'rviz-images', class: 'row'});
main.append(rqt.el('div', {class: 'row'}, rqt.el('label', {}, 'Fixed Frame ', fixedInput),
  rqt.el('button', {id: 'rviz-top', text: 'Top view'}),
  rqt.el('button', {id: 'rviz-save', text: 'Save Config As...'}), note),
rqt.el('div', {class: 'row', id: 'rviz-tools'}, ...toolButtons), list, view, imagePanel);
fixedInput.addEventListener('change', () => { state.fixedFrame = fixedInput.value.trim() || 'map'; });

// One line per display of the config: name, class, topic and its status.
export const listDisplays = (displays) => {
  for (const d of displays) {
    list.append(rqt.el('li', {'data-name': d.name}, `${d.name} (${d.class.split('/').pop()}`
      + `${d.topic ? ' ' + d.topic : ''}): `, rqt.el('span', {class: 'status', text: d.enabled ? 'OK' : 'disabled'})));
  }
};

export const setStatus = (name, text) => {
  // Unchanged: no DOM write (each TF answer sets the TF and RobotModel statuses again, and
  // a write, even of the same text, makes the next frame redo style and layout).
  if (state.status[name] === text) return;
  state.status[name] = text;
  const item = document.querySelector(`#rviz-displays li[data-name="${CSS.escape(name)}"] .status`);
  if (item) item.textContent = text;
};
