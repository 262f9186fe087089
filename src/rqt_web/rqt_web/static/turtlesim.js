'use strict';
// Turtlesim: the live canvas of every running turtlesim (its hidden ~/_canvas topic, sent
// only while this page watches) and keyboard teleop with turtle_teleop_key's keys.
(() => {
  const main = document.getElementById('main');
  const help = rqt.el('p', {class: 'keys', text:
    'Click a canvas, then: arrow keys move the turtle; G|B|V|C|D|E|R|T rotate to absolute orientations; F cancels a rotation.'});
  const area = rqt.el('div', {class: 'row', id: 'canvases'});
  const none = rqt.el('p', {id: 'no-turtlesim', text: 'No turtlesim is running (start one: ros2 run turtlesim turtlesim_node).'});
  main.append(help, none, area);

  const ROTATIONS = {g: 0.0, t: 0.7854, r: 1.5708, e: 2.3562, d: 3.1416, c: -2.3562, v: -1.5708, b: -0.7854};
  const ARROWS = ['ArrowUp', 'ArrowDown', 'ArrowLeft', 'ArrowRight'];
  const views = new Map();  // canvas topic -> {canvas, select, ...}
  // Figures the benchmark reads: frames drawn, and publish-to-draw latencies (ms).
  window.rqtStats = {frames: 0, latencies: []};
  let goalCounter = 0;

  const makeView = (topic, nodeName) => {
    const canvas = rqt.el('canvas', {class: 'turtlesim', width: 500, height: 500, tabindex: 0, 'data-topic': topic});
    const select = rqt.el('select', {class: 'turtle'});
    const info = rqt.el('div', {class: 'keys'});
    const panel = rqt.el('div', {class: 'panel'}, rqt.el('h3', {text: nodeName}),
      rqt.el('label', {}, 'Drive ', select), canvas, info);
    area.append(panel);
    const view = {topic, canvas, select, info, panel, decoding: false, next: null, turtles: []};
    canvas.addEventListener('click', () => canvas.focus());
    canvas.addEventListener('keydown', (event) => onKey(view, event));
    rqt.send({op: 'canvas', topic});
    return view;
  };

  const onKey = (view, event) => {
    const turtle = view.select.value;
    if (!turtle) return;
    const key = event.key.length === 1 ? event.key.toLowerCase() : event.key;
    if (ARROWS.includes(key)) {
      rqt.send({op: 'teleop', topic: `${turtle}/cmd_vel`, key});
    } else if (key in ROTATIONS) {
      goalCounter += 1;
      rqt.send({op: 'goal', id: `rotate-${goalCounter}`, action: `${turtle}/rotate_absolute`,
        type: 'turtlesim/action/RotateAbsolute', values: {theta: ROTATIONS[key]}});
    } else if (key === 'f') {
      rqt.send({op: 'cancel'});
    } else {
      return;
    }
    event.preventDefault();
  };

  const draw = async (view, header, bytes) => {
    if (view.decoding) { view.next = [header, bytes]; return; }
    view.decoding = true;
    try {
      const bitmap = await createImageBitmap(new Blob([bytes], {type: 'image/png'}));
      view.canvas.getContext('2d').drawImage(bitmap, 0, 0);
      bitmap.close();
      const stamp = /stamp=(\d+)/.exec(header.label || '');
      const stats = window.rqtStats;
      stats.frames += 1;
      if (stamp) {
        stats.latencies.push(Date.now() - Number(stamp[1]) / 1e6);
        if (stats.latencies.length > 2000) stats.latencies.splice(0, 1000);
      }
      view.canvas.dataset.frames = String(Number(view.canvas.dataset.frames || 0) + 1);
    } finally {
      view.decoding = false;
    }
    if (view.next) {
      const [nextHeader, nextBytes] = view.next;
      view.next = null;
      draw(view, nextHeader, nextBytes);
    }
  };

  rqt.on('binary', (buffer) => {
    const bytes = new Uint8Array(buffer);
    const split = bytes.indexOf(10);
    const header = JSON.parse(new TextDecoder().decode(bytes.subarray(0, split)));
    const view = views.get(header.topic);
    if (view) draw(view, header, bytes.subarray(split + 1));
  });

  rqt.on('graph', ({graph}) => {
    const seen = new Set();
    for (const node of graph.nodes) {
      for (const [topic, types] of node.pubs) {
        if (!topic.endsWith('/_canvas') || types[0] !== 'std_msgs/msg/UInt8MultiArray') continue;
        seen.add(topic);
        const view = views.get(topic) || makeView(topic, node.name);
        views.set(topic, view);
        const turtles = node.subs.filter(([name]) => name.endsWith('/cmd_vel')).map(([name]) => name.slice(0, -'/cmd_vel'.length));
        if (JSON.stringify(turtles) !== JSON.stringify(view.turtles)) {
          const previous = view.select.value;
          view.turtles = turtles;
          view.select.replaceChildren(...turtles.map((name) => rqt.el('option', {value: name, text: name})));
          if (turtles.includes(previous)) view.select.value = previous;
        }
      }
    }
    for (const [topic, view] of views) {
      if (!seen.has(topic)) {
        view.panel.remove();
        views.delete(topic);
        rqt.send({op: 'uncanvas', topic});
      }
    }
    none.hidden = views.size > 0;
  });

  rqt.on('goal_result', (message) => { for (const view of views.values()) view.info.textContent = `rotation ${message.status.toLowerCase()}`; });
  rqt.on('error', (message) => { for (const view of views.values()) view.info.textContent = message.error; });
  rqt.onOpen.push(() => {
    for (const topic of views.keys()) rqt.send({op: 'canvas', topic});
    rqt.send({op: 'graph'});
  });
})();
