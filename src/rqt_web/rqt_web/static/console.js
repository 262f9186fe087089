'use strict';
// Console, as rqt_console: /rosout with severity, node and text filters, pause and clear.
(() => {
  const main = document.getElementById('main');
  const LEVELS = ['DEBUG', 'INFO', 'WARN', 'ERROR', 'FATAL'];
  const KEEP = 5000;  // messages kept in the page (older ones are dropped)
  const SHOWN = 500;  // newest matching messages drawn
  const boxes = {};
  const severity = rqt.el('span', {id: 'severities'});
  for (const level of LEVELS) {
    const box = rqt.el('input', {type: 'checkbox', 'data-level': level});
    box.checked = true;
    boxes[level] = box;
    severity.append(rqt.el('label', {}, box, ` ${level} `));
  }
  const node = rqt.el('select', {id: 'node-filter'}, rqt.el('option', {value: '', text: 'all nodes'}));
  const text = rqt.el('input', {type: 'text', id: 'text-filter', placeholder: 'message contains...'});
  const pause = rqt.el('button', {id: 'pause', text: 'Pause'});
  const clear = rqt.el('button', {id: 'clear', text: 'Clear'});
  const count = rqt.el('span', {id: 'count', class: 'keys'});
  const body = rqt.el('tbody', {id: 'log'});
  main.append(rqt.el('div', {class: 'row'}, severity, node, text, pause, clear, count),
    rqt.el('div', {class: 'scroll'}, rqt.el('table', {class: 'console-table'}, rqt.el('thead', {}, rqt.el('tr', {},
      ...['#', 'Message', 'Severity', 'Node', 'Stamp', 'Location'].map((h) => rqt.el('th', {text: h})))), body)));

  let entries = [];
  let counter = 0;
  let paused = false;
  let scheduled = false;
  const nodes = new Set();

  const stamp = (seconds) => {
    const date = new Date(seconds * 1000);
    return `${date.toLocaleTimeString()}.${String(Math.floor((seconds % 1) * 1e3)).padStart(3, '0')}`;
  };

  const draw = () => {
    scheduled = false;
    const wanted = entries.filter((e) => boxes[e.severity]?.checked !== false
      && (!node.value || e.node === node.value)
      && (!text.value || e.message.includes(text.value)));
    body.replaceChildren(...wanted.slice(-SHOWN).reverse().map((e) => rqt.el('tr', {class: `sev-${e.severity}`},
      rqt.el('td', {text: e.index}), rqt.el('td', {class: 'message', text: e.message}),
      rqt.el('td', {text: e.severity}), rqt.el('td', {text: e.node}),
      rqt.el('td', {text: stamp(e.stamp)}), rqt.el('td', {text: `${e.file.split('/').pop()}:${e.line}`, title: e.file}))));
    count.textContent = `Displaying ${Math.min(wanted.length, SHOWN)} of ${entries.length} messages${paused ? ' (paused)' : ''}`;
  };
  const redraw = () => { if (!scheduled) { scheduled = true; requestAnimationFrame(draw); } };

  rqt.on('log', (message) => {
    if (paused) return;
    for (const entry of message.entries) {
      counter += 1;
      entries.push({...entry, index: counter});
      if (!nodes.has(entry.node)) {
        nodes.add(entry.node);
        node.append(rqt.el('option', {value: entry.node, text: entry.node}));
      }
    }
    if (entries.length > KEEP) entries = entries.slice(-KEEP);
    redraw();
  });
  pause.addEventListener('click', () => {
    paused = !paused;
    pause.textContent = paused ? 'Resume' : 'Pause';
    redraw();
  });
  clear.addEventListener('click', () => { entries = []; redraw(); });
  for (const control of [node, text, ...Object.values(boxes)]) control.addEventListener('input', redraw);
  rqt.onOpen.push(() => { entries = []; counter = 0; rqt.send({op: 'console'}); });
})();
