'use strict';
// Foxglove: how to open this machine's ROS graph in Foxglove or Lichtblick, and whether
// foxglove_bridge runs (a node named foxglove_bridge in the graph; its `port` parameter).
(() => {
  const main = document.getElementById('main');
  const state = rqt.el('p', {id: 'foxglove-state', text: 'Looking for foxglove_bridge...'});
  const url = rqt.el('code', {id: 'foxglove-url', text: 'ws://localhost:8765'});
  const steps = rqt.el('ol', {},
    rqt.el('li', {}, 'Start the bridge: ', rqt.el('code', {
      text: 'ros2 launch foxglove_bridge foxglove_bridge_launch.xml'}), ' (or ',
      rqt.el('code', {text: 'ros2 run foxglove_bridge foxglove_bridge'}), ').'),
    rqt.el('li', {}, 'Foxglove (app or desktop): Open connection, Foxglove WebSocket, URL ',
      url, '. It speaks foxglove.sdk.v1.'),
    rqt.el('li', {}, 'Lichtblick: Open connection, Foxglove WebSocket, the same URL. ' +
      'Lichtblick 1.28 offers foxglove.sdk.v1 too and is served that; older versions ' +
      'speak foxglove.websocket.v1. The bridge serves both on one port.'),
    rqt.el('li', {}, 'From another machine: start the bridge with ',
      rqt.el('code', {text: 'address:=0.0.0.0'}),
      ' (it listens on 127.0.0.1 by default) and use this machine\'s address.'));
  main.append(rqt.el('h1', {text: 'Foxglove and Lichtblick'}), state, steps);

  const PERIOD_MS = 2000;
  const check = async () => {
    try {
      const graph = await rqt.get('/api/graph');
      const node = (graph.nodes || []).find((n) => (n.name || '').endsWith('/foxglove_bridge'));
      if (!node) {
        state.textContent = 'foxglove_bridge is not running.';
        state.className = 'stopped';
        return;
      }
      let port = 8765;
      try {
        const params = await rqt.get(`/api/parameters?node=${encodeURIComponent(node.name)}`);
        const entry = (params.parameters || []).find((p) => p.name === 'port');
        if (entry && Number(entry.value) > 0) port = Number(entry.value);
      } catch (error) { /* the port stays upstream's default */ }
      url.textContent = `ws://${location.hostname || 'localhost'}:${port}`;
      state.textContent = `foxglove_bridge is running (${node.name}), port ${port}.`;
      state.className = 'running';
    } catch (error) {
      state.textContent = `Cannot read the ROS graph: ${error.message}`;
    } finally {
      setTimeout(check, PERIOD_MS);
    }
  };
  check();
})();
