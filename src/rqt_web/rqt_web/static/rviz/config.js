// The .rviz file the page shows (?config=, read by the server), or rviz2's default displays.
import {note} from './panel.js';
import {params, state} from './state.js';

const DEFAULT_DISPLAYS = [
  {class: 'rviz_default_plugins/Grid', name: 'Grid', enabled: true},
  {class: 'rviz_default_plugins/TF', name: 'TF', enabled: true},
  {class: 'rviz_default_plugins/RobotModel', name: 'RobotModel', enabled: true,
    topic: '/robot_description', alpha: 1}];

export async function loadConfig() {
  const path = params.get('config');
  if (!path) return {fixed_frame: state.fixedFrame, background: state.background, displays: DEFAULT_DISPLAYS};
  try {
    return await rqt.get(`/api/rviz/config?path=${encodeURIComponent(path)}`);
  } catch (error) {
    note.textContent = String(error.message || error);
    return {fixed_frame: state.fixedFrame, background: state.background, displays: DEFAULT_DISPLAYS};
  }
}
