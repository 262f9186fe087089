// Save Config: the page's setup in upstream rviz2's .rviz YAML layout (keys and nesting as
// rviz2 writes them: maps with sorted keys, lists of maps), downloaded as a file.
import {view} from './panel.js';
import {params, state} from './state.js';

const yamlScalar = (v) => {
  if (v === null || v === undefined) return '~';
  if (typeof v !== 'string') return String(v);
  // Quoted when YAML would read it as something else (a number, bool, null) or choke.
  const plain = v !== '' && !/^[\s\-?:,\[\]{}#&*!|>'"%@`]/.test(v) && !/(:\s|\s#|:$|\s$|[\n\t"])/.test(v)
    && !/^(true|false|yes|no|on|off|y|n|null|~)$/i.test(v) && !/^([-+]?[\d.][\d._:eE+-]*|[-+]?\.(inf|nan))$/i.test(v);
  return plain ? v : JSON.stringify(v);
};
const toYaml = (map, indent = 0) => {
  const pad = ' '.repeat(indent);
  const out = [];
  for (const key of Object.keys(map).sort()) {
    const v = map[key];
    if (Array.isArray(v)) {
      out.push(v.length ? `${pad}${key}:` : `${pad}${key}: []`);
      for (const item of v) {
        const inner = item && typeof item === 'object' ? toYaml(item, indent + 4) : [];
        if (inner.length) out.push(`${pad}  - ${inner[0].trimStart()}`, ...inner.slice(1));
        else out.push(`${pad}  - ${item && typeof item === 'object' ? '{}' : yamlScalar(item)}`);
      }
    } else if (v && typeof v === 'object') {
      out.push(...(Object.keys(v).length ? [`${pad}${key}:`, ...toYaml(v, indent + 2)] : [`${pad}${key}: {}`]));
    } else out.push(`${pad}${key}: ${yamlScalar(v)}`);
  }
  return out;
};
const DEFAULT_TOOLS = [['Interact'], ['MoveCamera'], ['Select'], ['FocusCamera'], ['Measure'],
  ['SetInitialPose', '/initialpose'], ['SetGoal', '/goal_pose'], ['PublishPoint', '/clicked_point']]
  .map(([name, topic]) => ({class: `rviz_default_plugins/${name}`, topic}));
const round = (x) => Number(x.toFixed(6));

// state.saveConfig() gives the file's text (tests read it); the button downloads it.
export function installSave(config, camera, controls) {
  state.saveConfig = () => {
    const displays = state.displays.map((d) => {
      const out = {...(d.settings || {}), Class: d.class, Enabled: d.enabled, Name: d.name, Value: d.enabled};
      const key = d.class.endsWith('/RobotModel') ? 'Description Topic' : 'Topic';
      const topic = out[key] && typeof out[key] === 'object' ? out[key] : {};  // QoS kept
      delete out.Topic;
      delete out['Description Topic'];
      if (d.topic) out[key] = {...topic, Value: d.topic};
      return out;
    });
    const tools = ((config.tools || []).length ? config.tools : DEFAULT_TOOLS).map((t) => (
      t.topic ? {Class: t.class, Topic: {Value: t.topic}} : {Class: t.class}));
    const offset = camera.position.clone().sub(controls.target);
    const distance = offset.length();
    const common = {Name: 'Current View', 'Near Clip Distance': 0.01, 'Target Frame': '<Fixed Frame>'};
    const current = String((config.view || {}).Class || '').endsWith('TopDownOrtho')
      ? {...common, Class: 'rviz_default_plugins/TopDownOrtho', Angle: 0, 'Invert Z Axis': false,
        // the height the page's 45-degree camera looks from, back to pixels per metre
        Scale: round(view.clientHeight / 2 / (offset.z * Math.tan(Math.PI / 8))),
        Value: 'TopDownOrtho (rviz_default_plugins)', X: round(controls.target.x), Y: round(controls.target.y)}
      : {...common, Class: 'rviz_default_plugins/Orbit', Distance: round(distance),
        'Focal Point': {X: round(controls.target.x), Y: round(controls.target.y), Z: round(controls.target.z)},
        Pitch: round(Math.asin(offset.z / distance)),
        Value: 'Orbit (rviz)', Yaw: round((Math.atan2(offset.y, offset.x) + 2 * Math.PI) % (2 * Math.PI))};
    const [br, bg, bb] = config.background;
    return toYaml({
      Panels: [
        {Class: 'rviz_common/Displays', 'Help Height': 78, Name: 'Displays',
          'Property Tree Widget': {Expanded: ['/Global Options1'], 'Splitter Ratio': 0.5}, 'Tree Height': 557},
        {Class: 'rviz_common/Views', Expanded: ['/Current View1'], Name: 'Views', 'Splitter Ratio': 0.5}],
      'Visualization Manager': {
        Class: '', Displays: displays, Enabled: true,
        'Global Options': {'Background Color': `${br}; ${bg}; ${bb}`, 'Fixed Frame': state.fixedFrame,
          'Frame Rate': 30},
        Name: 'root', Tools: tools, Transformation: {Current: {Class: 'rviz_default_plugins/TF'}},
        Value: true, Views: {Current: current, Saved: null}},
      'Window Geometry': {Displays: {collapsed: false}, Height: window.innerHeight, 'Hide Left Dock': false,
        'Hide Right Dock': false, Views: {collapsed: false}, Width: window.innerWidth, X: 0, Y: 0},
    }).join('\n') + '\n';
  };
  document.getElementById('rviz-save').addEventListener('click', () => {
    const link = rqt.el('a', {href: URL.createObjectURL(new Blob([state.saveConfig()], {type: 'text/yaml'})),
      download: (params.get('config') || 'config.rviz').split('/').pop()});
    link.click();
  });
}
