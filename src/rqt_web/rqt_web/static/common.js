// Shared by every page: the WebSocket to the server, JSON helpers, small DOM helpers.
'use strict';

const rqt = {
  page: document.body.dataset.page,
  handlers: {},
  socket: null,
  pending: [],
  onOpen: [],
};

rqt.el = (tag, attrs = {}, ...children) => {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs)) {
    if (key === 'text') node.textContent = value;
    else if (key.startsWith('on')) node.addEventListener(key.slice(2), value);
    else if (value !== undefined && value !== null && value !== false) node.setAttribute(key, value);
  }
  for (const child of children) node.append(child);
  return node;
};

rqt.status = (text) => { document.getElementById('status').textContent = text; };

rqt.get = async (path) => {
  const response = await fetch(path, {credentials: 'same-origin'});
  if (!response.ok) throw new Error(await response.text());
  return response.json();
};

rqt.post = async (path, body) => {
  const response = await fetch(path, {
    method: 'POST', credentials: 'same-origin',
    headers: {'Content-Type': 'application/json'}, body: JSON.stringify(body)});
  if (!response.ok) throw new Error(await response.text());
  return response.json();
};

rqt.on = (op, handler) => { rqt.handlers[op] = handler; };

rqt.send = (message) => {
  if (rqt.socket && rqt.socket.readyState === WebSocket.OPEN) rqt.socket.send(JSON.stringify(message));
  else rqt.pending.push(message);
};

rqt.connect = () => {
  const scheme = location.protocol === 'https:' ? 'wss' : 'ws';
  const socket = new WebSocket(`${scheme}://${location.host}/ws`);
  socket.binaryType = 'arraybuffer';
  rqt.socket = socket;
  socket.onopen = () => {
    rqt.status('connected');
    for (const callback of rqt.onOpen) callback();
    for (const message of rqt.pending.splice(0)) socket.send(JSON.stringify(message));
  };
  socket.onmessage = (event) => {
    if (typeof event.data !== 'string') {
      if (rqt.handlers.binary) rqt.handlers.binary(event.data);
      return;
    }
    const message = JSON.parse(event.data);
    const handler = rqt.handlers[message.op];
    if (handler) handler(message);
  };
  socket.onclose = () => {
    rqt.status('disconnected: retrying...');
    setTimeout(rqt.connect, 1000);
  };
};

// Names and types of the graph, shared by the pages that list them.
rqt.hidden = (name) => name.split('/').some((token) => token.startsWith('_'));

for (const link of document.querySelectorAll('nav a')) {
  if (link.dataset.for === rqt.page) link.classList.add('current');
}
window.addEventListener('DOMContentLoaded', () => rqt.connect());
