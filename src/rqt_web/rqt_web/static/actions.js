'use strict';
// Actions: pick an action, fill the goal form, send; feedback and result arrive live; cancel.
(() => {
  const main = document.getElementById('main');
  const select = rqt.el('select', {id: 'action'});
  const formBox = rqt.el('div', {id: 'goal-form'});
  const send = rqt.el('button', {id: 'send-goal', text: 'Send goal'});
  const cancel = rqt.el('button', {id: 'cancel-goal', text: 'Cancel goal'});
  const status = rqt.el('div', {id: 'goal-status'});
  const feedback = rqt.el('pre', {id: 'feedback'});
  const result = rqt.el('pre', {id: 'result'});
  main.append(rqt.el('div', {class: 'panel'}, rqt.el('label', {}, 'Action ', select), ' ', send, ' ', cancel,
    rqt.el('h3', {text: 'Goal'}), formBox, status,
    rqt.el('h3', {text: 'Feedback'}), feedback, rqt.el('h3', {text: 'Result'}), result));

  let actions = [];
  let formFor = null;
  let goalId = null;
  let counter = 0;
  const current = () => actions.find(([name]) => name === select.value);
  const say = (text, ok = true) => status.replaceChildren(rqt.el('div', {class: ok ? 'ok' : 'error', text}));

  const showForm = async () => {
    const entry = current();
    if (!entry || formFor === entry[0]) return;
    formFor = entry[0];
    const description = await rqt.get(`/api/interface?kind=action&part=goal&type=${encodeURIComponent(entry[1][0])}`);
    formBox.replaceChildren(description.error ? rqt.el('div', {class: 'error', text: description.error}) : rqt.forms.build(description.fields));
  };
  select.addEventListener('change', showForm);

  send.addEventListener('click', () => {
    const entry = current();
    if (!entry) return;
    const collected = rqt.forms.collect(formBox);
    if (collected.error) { say(`Not sent: ${collected.error}`, false); return; }
    counter += 1;
    goalId = `goal-${counter}`;
    feedback.textContent = '';
    result.textContent = '';
    say('sending goal...');
    rqt.send({op: 'goal', id: goalId, action: entry[0], type: entry[1][0], values: collected.values});
  });
  cancel.addEventListener('click', () => { if (goalId) rqt.send({op: 'cancel', id: goalId}); });

  rqt.on('goal_accepted', (m) => { if (m.id === goalId) say('Goal accepted'); });
  rqt.on('goal_rejected', (m) => { if (m.id === goalId) say('Goal was rejected', false); });
  rqt.on('feedback', (m) => { if (m.id === goalId) feedback.textContent = rqt.forms.yaml(m.feedback); });
  rqt.on('goal_result', (m) => {
    if (m.id !== goalId) return;
    say(`Goal finished with status: ${m.status}`, m.status === 'SUCCEEDED');
    result.textContent = rqt.forms.yaml(m.result);
  });
  rqt.on('error', (m) => say(m.error, false));
  rqt.on('graph', ({graph}) => {
    if (JSON.stringify(graph.actions) === JSON.stringify(actions)) return;
    const previous = select.value;
    actions = graph.actions;
    select.replaceChildren(...actions.map(([name, types]) => rqt.el('option', {value: name, text: `${name}  [${types[0]}]`})));
    if (previous && actions.some(([name]) => name === previous)) select.value = previous;
    showForm();
  });
  rqt.onOpen.push(() => rqt.send({op: 'graph'}));
})();
