'use strict';
// Topics, as rqt_topic: every topic with its type; tick Monitor for its rate, bandwidth
// and latest message; publish a message from a form generated from a type.
(() => {
  const main = document.getElementById('main');
  const body = rqt.el('tbody', {id: 'topics'});
  const topicInput = rqt.el('input', {type: 'text', id: 'pub-topic', placeholder: '/turtle1/cmd_vel', size: 28});
  const typeInput = rqt.el('input', {type: 'text', id: 'pub-type', placeholder: 'geometry_msgs/msg/Twist', size: 28});
  const formBox = rqt.el('div', {id: 'pub-form'});
  const publish = rqt.el('button', {id: 'publish', text: 'Publish'});
  const message = rqt.el('div', {id: 'message'});
  main.append(
    rqt.el('table', {}, rqt.el('thead', {}, rqt.el('tr', {},
      ...['Monitor', 'Topic', 'Type', 'Pubs', 'Subs', 'Hz', 'Bandwidth', 'Latest message'].map((h) => rqt.el('th', {text: h})))), body),
    rqt.el('div', {class: 'panel'}, rqt.el('h3', {text: 'Publish a message'}),
      rqt.el('label', {}, 'Topic ', topicInput), ' ', rqt.el('label', {}, 'Type ', typeInput), ' ', publish,
      formBox, message));

  const rows = new Map();  // topic -> {row, cells}
  const counts = (graph, topic) => {
    let pubs = 0; let subs = 0;
    for (const node of graph.nodes) {
      if (node.pubs.some(([name]) => name === topic)) pubs += 1;
      if (node.subs.some(([name]) => name === topic)) subs += 1;
    }
    return [pubs, subs];
  };

  const human = (bytesPerSecond) => (bytesPerSecond >= 1e6 ? `${(bytesPerSecond / 1e6).toFixed(2)} MB/s`
    : bytesPerSecond >= 1e3 ? `${(bytesPerSecond / 1e3).toFixed(2)} KB/s` : `${bytesPerSecond.toFixed(0)} B/s`);

  rqt.on('graph', ({graph}) => {
    const shown = graph.topics.filter(([name]) => !rqt.hidden(name));
    const names = new Set(shown.map(([name]) => name));
    for (const [topic, entry] of rows) {
      if (!names.has(topic)) { entry.row.remove(); rows.delete(topic); }
    }
    for (const [topic, types] of shown) {
      let entry = rows.get(topic);
      if (!entry) {
        const monitor = rqt.el('input', {type: 'checkbox', 'data-topic': topic});
        const cells = {pubs: rqt.el('td'), subs: rqt.el('td'), hz: rqt.el('td', {class: 'hz'}), bw: rqt.el('td', {class: 'bw'}), latest: rqt.el('pre', {class: 'latest'})};
        const row = rqt.el('tr', {'data-topic': topic}, rqt.el('td', {}, monitor), rqt.el('td', {text: topic}),
          rqt.el('td', {text: types[0]}), cells.pubs, cells.subs, cells.hz, cells.bw, rqt.el('td', {}, cells.latest));
        monitor.addEventListener('change', () => {
          rqt.send({op: monitor.checked ? 'monitor' : 'unmonitor', topic, type: types[0]});
          if (!monitor.checked) { cells.hz.textContent = ''; cells.bw.textContent = ''; cells.latest.textContent = ''; }
        });
        row.addEventListener('dblclick', () => { topicInput.value = topic; typeInput.value = types[0]; showForm(); });
        entry = {row, cells, monitor, type: types[0]};
        rows.set(topic, entry);
        body.append(row);
      }
      const [pubs, subs] = counts(graph, topic);
      entry.cells.pubs.textContent = pubs;
      entry.cells.subs.textContent = subs;
    }
  });

  rqt.on('monitor', (report) => {
    const entry = rows.get(report.topic);
    if (!entry || !entry.monitor.checked) return;
    entry.cells.hz.textContent = report.hz === null ? 'no messages' : report.hz.toFixed(2);
    entry.cells.bw.textContent = report.bw === null ? '' : human(report.bw);
    entry.cells.latest.textContent = report.latest ?? '';
  });

  let formType = null;
  const showForm = async () => {
    const type = typeInput.value.trim();
    if (!type || type === formType) return;
    formType = type;
    const description = await rqt.get(`/api/interface?kind=msg&type=${encodeURIComponent(type)}`);
    formBox.replaceChildren(description.error ? rqt.el('div', {class: 'error', text: description.error}) : rqt.forms.build(description.fields));
  };
  typeInput.addEventListener('change', showForm);

  publish.addEventListener('click', async () => {
    await showForm();
    const collected = rqt.forms.collect(formBox);
    if (collected.error) { message.replaceChildren(rqt.el('div', {class: 'error', text: `Not sent: ${collected.error}`})); return; }
    const answer = await rqt.post('/api/topic/publish', {topic: topicInput.value.trim(), type: typeInput.value.trim(), values: collected.values});
    message.replaceChildren(answer.error ? rqt.el('div', {class: 'error', text: answer.error})
      : rqt.el('div', {class: 'ok', text: `published to ${topicInput.value.trim()}`}));
  });

  rqt.onOpen.push(() => {
    rqt.send({op: 'graph'});
    for (const [topic, entry] of rows) if (entry.monitor.checked) rqt.send({op: 'monitor', topic, type: entry.type});
  });
})();
