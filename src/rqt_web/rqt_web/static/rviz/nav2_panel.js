// The "Navigation 2" panel (nav2_rviz_plugins) and what its Nav2 Goal tool sends: Startup,
// Pause, Resume and Reset of both lifecycle managers, their state (is_active), the
// navigate_to_pose goal's feedback and result, and Cancel. Shown when the config's tools
// name nav2_rviz_plugins/GoalTool, as nav2_default_view.rviz does.
import {note} from './panel.js';
import {state} from './state.js';

const secs = (value) => `${Number(value || 0).toFixed(1)} s`;

export function add(ctx) {
  const nav2Tool = (ctx.config.tools || []).some((t) => t.class.endsWith('/GoalTool'));
  const toolButton = document.getElementById('rviz-tool-nav2goal');
  if (!nav2Tool) {
    toolButton.hidden = true;
    return;
  }
  const field = (id) => rqt.el('span', {id: `nav2-${id}`, text: '-'});
  const fields = Object.fromEntries(['navigation', 'localization', 'status', 'distance', 'time',
    'recoveries', 'result'].map((k) => [k, field(k)]));
  const button = (command, text) => {
    const b = rqt.el('button', {id: `nav2-${command}`, text});
    b.addEventListener('click', async () => {
      note.textContent = `Navigation 2: ${text}...`;
      try {
        const answer = await rqt.post(command === 'cancel' ? '/api/rviz/nav2/cancel'
          : '/api/rviz/nav2/manage', {command});
        note.textContent = `Navigation 2: ${text}: ${JSON.stringify(answer.success ?? answer.canceled)}`;
      } catch (error) {
        note.textContent = `Navigation 2: ${error.message || error}`;
      }
      await refresh();
    });
    return b;
  };
  const panel = rqt.el('div', {id: 'nav2-panel', class: 'row'},
    rqt.el('b', {text: 'Navigation 2 '}),
    button('startup', 'Startup'), button('pause', 'Pause'), button('resume', 'Resume'),
    button('reset', 'Reset'), button('cancel', 'Cancel'),
    rqt.el('span', {}, ' Navigation: ', fields.navigation, ' Localization: ', fields.localization,
      ' Feedback: ', fields.status, ' Distance remaining: ', fields.distance, ' Time taken: ',
      fields.time, ' Recoveries: ', fields.recoveries, ' ', fields.result));
  document.getElementById('rviz-tools').after(panel);

  const refresh = async () => {
    const s = await rqt.get('/api/rviz/nav2/state');
    state.nav2 = s;
    fields.navigation.textContent = s.navigation;
    fields.localization.textContent = s.localization;
    fields.status.textContent = s.status;
    const f = s.feedback;
    fields.distance.textContent = f ? `${f.distance_remaining.toFixed(2)} m` : '-';
    fields.time.textContent = f ? secs(f.navigation_time) : '-';
    fields.recoveries.textContent = f ? String(f.number_of_recoveries) : '-';
    fields.result.textContent = s.result ? `result: ${s.status} ${s.result.error_code}`
      + `${s.result.error_msg ? ' ' + s.result.error_msg : ''}` : '';
  };
  const tick = async () => {
    try {
      await refresh();
    } catch (error) {
      note.textContent = String(error.message || error);
    }
    setTimeout(tick, 300);
  };
  tick();
  ctx.sendNav2Goal = async (at, yaw) => {
    try {
      const answer = await rqt.post('/api/rviz/nav2/goal', {frame: state.fixedFrame, x: at.x, y: at.y, yaw});
      note.textContent = `Nav2 Goal: ${answer.accepted ? 'accepted' : 'rejected'} (${at.x.toFixed(2)}, ${at.y.toFixed(2)})`;
    } catch (error) {
      note.textContent = `Nav2 Goal: ${error.message || error}`;
    }
    await refresh();
  };
}
