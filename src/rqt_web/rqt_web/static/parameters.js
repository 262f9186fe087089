'use strict';
// Parameters, as rqt_reconfigure: pick a node, see its parameters with their descriptors'
// ranges, set one (checked against type and range in the page, then by the node).
(() => {
  const main = document.getElementById('main');
  const nodeSelect = rqt.el('select', {id: 'node'});
  const refresh = rqt.el('button', {id: 'refresh', text: 'Refresh'});
  const message = rqt.el('div', {id: 'message'});
  const body = rqt.el('tbody', {id: 'parameters'});
  main.append(rqt.el('div', {class: 'row'}, rqt.el('label', {}, 'Node ', nodeSelect), refresh),
    message, rqt.el('table', {}, rqt.el('thead', {}, rqt.el('tr', {},
      ...['Parameter', 'Type', 'Value', 'Range', 'Description', ''].map((h) => rqt.el('th', {text: h})))), body));

  let nodes = [];
  const show = (text, ok) => message.replaceChildren(rqt.el('div', {class: ok ? 'ok' : 'error', text}));

  const parse = (info, raw) => {
    if (info.type === 'bool') return raw;
    if (info.type === 'integer') {
      if (!/^[+-]?\d+$/.test(raw.trim())) throw new Error(`parameter '${info.name}' must be an integer, got ${JSON.stringify(raw)}`);
      return Number(raw);
    }
    if (info.type === 'double') {
      const value = Number(raw);
      if (raw.trim() === '' || !Number.isFinite(value)) throw new Error(`parameter '${info.name}' must be a number, got ${JSON.stringify(raw)}`);
      return value;
    }
    return raw;
  };

  const load = async () => {
    const node = nodeSelect.value;
    if (!node) return;
    const answer = await rqt.get(`/api/parameters?node=${encodeURIComponent(node)}`);
    if (answer.error) { show(answer.error, false); return; }
    body.replaceChildren(...answer.parameters.map((info) => {
      let input;
      if (info.type === 'bool') {
        input = rqt.el('input', {type: 'checkbox', 'data-name': info.name});
        input.checked = info.value;
      } else {
        input = rqt.el('input', {type: 'text', 'data-name': info.name, value: Array.isArray(info.value) ? JSON.stringify(info.value) : String(info.value ?? '')});
      }
      const set = rqt.el('button', {text: 'Set', 'data-name': info.name, disabled: info.read_only || !['bool', 'integer', 'double', 'string'].includes(info.type)});
      set.addEventListener('click', async () => {
        let value;
        try {
          value = info.type === 'bool' ? input.checked : parse(info, input.value);
          if (info.range && (value < info.range.min || value > info.range.max)) {
            throw new Error(`parameter '${info.name}' must be in [${info.range.min}, ${info.range.max}], got ${value}`);
          }
        } catch (error) {
          input.classList.add('invalid');
          show(`Not sent: ${error.message}`, false);
          return;
        }
        input.classList.remove('invalid');
        const result = await rqt.post('/api/parameters/set', {node, name: info.name, value});
        if (result.error) show(result.error, false);
        else show(`Set parameter successful: ${info.name} = ${JSON.stringify(value)}`, true);
      });
      const range = info.range ? `[${info.range.min}, ${info.range.max}]${info.range.step ? ` step ${info.range.step}` : ''}` : '';
      return rqt.el('tr', {}, rqt.el('td', {text: info.name}), rqt.el('td', {text: info.type}),
        rqt.el('td', {}, input), rqt.el('td', {text: range}), rqt.el('td', {text: info.description}), rqt.el('td', {}, set));
    }));
  };

  rqt.on('graph', ({graph}) => {
    // Nodes that offer parameter services (rclpy and rclcpp nodes by default).
    const names = graph.nodes.filter((n) => n.services.some(([s]) => s === `${n.name}/list_parameters`)).map((n) => n.name);
    if (JSON.stringify(names) === JSON.stringify(nodes)) return;
    const previous = nodeSelect.value || new URLSearchParams(location.search).get('node');
    nodes = names;
    nodeSelect.replaceChildren(...nodes.map((n) => rqt.el('option', {value: n, text: n})));
    if (previous && nodes.includes(previous)) nodeSelect.value = previous;
    load();
  });
  nodeSelect.addEventListener('change', load);
  refresh.addEventListener('click', load);
  rqt.onOpen.push(() => rqt.send({op: 'graph'}));
})();
