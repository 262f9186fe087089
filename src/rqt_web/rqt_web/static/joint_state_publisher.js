'use strict';
// Joint State Publisher (joint_state_publisher_gui): one slider per movable joint of the
// robot on /robot_description, with its limits; mimic joints follow theirs (the node
// computes them). Randomize and Center as upstream. Positions go to the node on
// /joint_state_publisher_gui/sliders.
(() => {
  const TOPIC = '/joint_state_publisher_gui/sliders';
  const main = document.getElementById('main');
  const randomize = rqt.el('button', {id: 'jsp-randomize', text: 'Randomize'});
  const center = rqt.el('button', {id: 'jsp-center', text: 'Center'});
  const note = rqt.el('span', {id: 'jsp-note', class: 'keys'});
  const table = rqt.el('table', {id: 'jsp-sliders'});
  main.append(rqt.el('div', {class: 'row'}, randomize, center, note), table);
  const sliders = {};
  window.jsp = {sliders, published: 0};
  let count = -1;
  let touched = false;  // the user moved a slider: from then on the page owns the positions

  const publish = async () => {
    const names = Object.keys(sliders);
    if (!names.length) return;
    await rqt.post('/api/topic/publish', {topic: TOPIC, type: 'sensor_msgs/msg/JointState',
      values: {name: names, position: names.map((n) => Number(sliders[n].input.value))}});
    window.jsp.published += 1;
  };
  const build = (xml) => {
    table.replaceChildren();
    for (const key of Object.keys(sliders)) delete sliders[key];
    const robot = new DOMParser().parseFromString(xml, 'application/xml').documentElement;
    if (!robot || robot.nodeName !== 'robot') {
      note.textContent = 'the robot description is not a URDF <robot>';
      return;
    }
    for (const joint of robot.querySelectorAll(':scope > joint')) {
      const type = joint.getAttribute('type');
      if (!['revolute', 'continuous', 'prismatic'].includes(type) || joint.querySelector('mimic')) continue;
      const limit = joint.querySelector('limit');
      let lower = type === 'continuous' ? -Math.PI : Number(limit?.getAttribute('lower'));
      let upper = type === 'continuous' ? Math.PI : Number(limit?.getAttribute('upper'));
      if (!Number.isFinite(lower) || !Number.isFinite(upper)) { lower = -Math.PI; upper = Math.PI; }
      const zero = lower > 0 || upper < 0 ? (lower + upper) / 2 : 0;
      const name = joint.getAttribute('name');
      const value = rqt.el('span', {class: 'value', text: zero.toFixed(2)});
      const input = rqt.el('input', {type: 'range', min: lower, max: upper, step: (upper - lower) / 1000,
        value: zero, 'data-joint': name});
      input.addEventListener('input', () => { value.textContent = Number(input.value).toFixed(2); touched = true; publish(); });
      sliders[name] = {input, value, lower, upper, zero};
      table.append(rqt.el('tr', {}, rqt.el('td', {text: name}), rqt.el('td', {}, input), rqt.el('td', {}, value)));
    }
    note.textContent = Object.keys(sliders).length ? '' : 'no movable joints';
  };
  const setAll = (pick) => {
    for (const s of Object.values(sliders)) {
      s.input.value = pick(s);
      s.value.textContent = Number(s.input.value).toFixed(2);
    }
    touched = true;
    publish();
  };
  // Once a second again: a message sent before the node's subscription was discovered is
  // lost (volatile topic); the positions the sliders show then still reach the node.
  setInterval(() => { if (touched) publish(); }, 1000);
  randomize.addEventListener('click', () => setAll((s) => s.lower + Math.random() * (s.upper - s.lower)));
  center.addEventListener('click', () => setAll((s) => s.zero));
  const poll = async () => {
    try {
      const d = await rqt.get('/api/rviz/description?topic=/robot_description');
      if (d.count !== count) {
        count = d.count;
        if (d.urdf) build(d.urdf);
        else note.textContent = 'Waiting for robot_description on /robot_description...';
      }
    } catch (error) {
      note.textContent = String(error.message || error);
    }
    setTimeout(poll, 1000);
  };
  poll();
})();
