'use strict';
// Service Caller: pick a service, fill the form generated from its request type, call.
(() => {
  const main = document.getElementById('main');
  const select = rqt.el('select', {id: 'service'});
  const timeout = rqt.el('input', {id: 'timeout', type: 'text', value: '5', size: 4});
  const formBox = rqt.el('div', {id: 'request-form'});
  const call = rqt.el('button', {id: 'call', text: 'Call'});
  const message = rqt.el('div', {id: 'message'});
  const response = rqt.el('pre', {id: 'response'});
  main.append(rqt.el('div', {class: 'panel'},
    rqt.el('label', {}, 'Service ', select), ' ',
    rqt.el('label', {}, 'Timeout (s) ', timeout), ' ', call,
    rqt.el('h3', {text: 'Request'}), formBox, message,
    rqt.el('h3', {text: 'Response'}), response));

  let services = [];
  const current = () => services.find(([name]) => name === select.value);

  const listServices = (graph) => {
    const shown = graph.services.filter(([name]) => !rqt.hidden(name));
    const names = JSON.stringify(shown);
    if (names === JSON.stringify(services)) return;
    const previous = select.value || new URLSearchParams(location.search).get('service');
    services = shown;
    select.replaceChildren(...services.map(([name, types]) => rqt.el('option', {value: name, text: `${name}  [${types[0]}]`})));
    if (previous && services.some(([name]) => name === previous)) select.value = previous;
    showForm();
  };

  let formFor = null;
  const showForm = async () => {
    const entry = current();
    if (!entry || formFor === entry[0]) return;
    formFor = entry[0];
    const description = await rqt.get(`/api/interface?kind=srv&part=request&type=${encodeURIComponent(entry[1][0])}`);
    formBox.replaceChildren(description.error ? rqt.el('div', {class: 'error', text: description.error})
      : rqt.forms.build(description.fields));
    message.replaceChildren();
    response.textContent = '';
  };
  select.addEventListener('change', showForm);

  call.addEventListener('click', async () => {
    const entry = current();
    if (!entry) return;
    const collected = rqt.forms.collect(formBox);
    const seconds = Number(timeout.value);
    if (!collected.error && !(seconds > 0 && seconds <= 60)) collected.error = `timeout must be a number of seconds in (0, 60], got ${JSON.stringify(timeout.value)}`;
    if (collected.error) {
      message.replaceChildren(rqt.el('div', {class: 'error', text: `Not sent: ${collected.error}`}));
      return;
    }
    message.replaceChildren(rqt.el('div', {text: 'calling...'}));
    const answer = await rqt.post('/api/service/call', {name: entry[0], type: entry[1][0], values: collected.values, timeout: seconds});
    if (answer.error) {
      message.replaceChildren(rqt.el('div', {class: 'error', text: answer.error}));
      return;
    }
    message.replaceChildren(rqt.el('div', {class: 'ok', text: `answered in ${(answer.seconds * 1000).toFixed(1)} ms`}));
    response.textContent = rqt.forms.yaml(answer.response) || '(empty response)';
  });

  rqt.on('graph', (message) => listServices(message.graph));
  rqt.onOpen.push(() => rqt.send({op: 'graph'}));
})();
