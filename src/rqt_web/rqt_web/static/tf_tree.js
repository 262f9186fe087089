'use strict';
// TF Tree, as rqt_tf_tree: the frames tf2 knows, parent above child, each edge labelled with
// its broadcaster, average rate, buffer length, most recent and oldest transform. Laid out
// by dagre and drawn by cytoscape (as the Node Graph page); data from /api/tf/frames.
(() => {
  const main = document.getElementById('main');
  const refresh = rqt.el('button', {id: 'tf-refresh', text: 'Refresh'});
  const clear = rqt.el('button', {id: 'tf-clear', text: 'Clear buffer'});
  const auto = rqt.el('input', {type: 'checkbox', id: 'tf-auto'});
  auto.checked = true;
  const fit = rqt.el('button', {id: 'tf-fit', text: 'Fit in view'});
  const exportSvg = rqt.el('button', {id: 'tf-export-svg', text: 'Export SVG'});
  const exportPng = rqt.el('button', {id: 'tf-export-png', text: 'Export PNG'});
  const note = rqt.el('span', {id: 'tf-note', class: 'keys'});
  const box = rqt.el('div', {id: 'cy'});
  main.append(rqt.el('div', {class: 'row'}, refresh, clear,
    rqt.el('label', {}, auto, ' Auto refresh (1 s)'), fit, exportSvg, exportPng, note), box);

  const PERIOD_MS = 1000;
  let cy = null;
  let shownKey = '';

  const loadScript = (src) => new Promise((resolve, reject) => {
    const script = rqt.el('script', {src});
    script.onload = resolve;
    script.onerror = () => reject(new Error(src));
    document.head.append(script);
  });

  // Numbers as Python's str() writes them (rqt_tf_tree's labels): 10000.0, not 10000.
  const num = (value) => (typeof value === 'number' && Number.isInteger(value) ? value.toFixed(1) : String(value));
  // The label rqt_tf_tree (and view_frames) writes on the edge parent -> child.
  const edgeLabel = (info) => [
    `Broadcaster: ${info.broadcaster}`, `Average rate: ${num(info.rate)}`,
    `Buffer length: ${num(info.buffer_length)}`, `Most recent transform: ${num(info.most_recent_transform)}`,
    `Oldest transform: ${num(info.oldest_transform)}`].join('\n');

  const elements = (frames, time) => {
    const names = new Set();
    const items = [];
    for (const [child, info] of Object.entries(frames)) {
      names.add(child);
      names.add(info.parent);
      items.push({data: {id: `e:${info.parent}>${child}`, source: `f:${info.parent}`, target: `f:${child}`, label: edgeLabel(info)}});
    }
    if (names.size === 0) return [{data: {id: 'none', label: 'No tf data received', kind: 'legend'}}];
    const roots = [...names].filter((name) => !(name in frames));
    items.push({data: {id: 'legend', label: `Recorded at time: ${time.toFixed(3)}`, kind: 'legend'}});
    for (const root of roots) items.push({data: {id: `l:${root}`, source: 'legend', target: `f:${root}`, kind: 'legend'}});
    return [...[...names].sort().map((name) => ({data: {id: `f:${name}`, label: name, kind: 'frame'}})), ...items];
  };

  const render = (frames, time) => {
    // The structure decides the layout; labels (rates, times) change every refresh.
    const key = JSON.stringify(Object.entries(frames).map(([c, i]) => [c, i.parent]).sort());
    const items = elements(frames, time);
    if (key !== shownKey) {
      shownKey = key;
      cy.elements().remove();
      cy.add(items);
      cy.layout({name: 'dagre', rankDir: 'TB', nodeSep: 40, rankSep: 90, edgeSep: 20}).run();
      cy.fit(undefined, 20);
    } else {
      for (const item of items) {
        const element = cy.getElementById(item.data.id);
        if (element.nonempty()) element.data('label', item.data.label);
      }
    }
    const count = Object.keys(frames).length;
    note.textContent = `${count} transform${count === 1 ? '' : 's'}, updated ${new Date().toLocaleTimeString()}`;
    window.rqtTfTree = {
      frames: cy.nodes('[kind="frame"]').map((n) => n.data('label')),
      edges: cy.edges('[kind!="legend"]').map((e) => [e.source().data('label'), e.target().data('label'), e.data('label')]),
      updated: Date.now(),
    };
  };

  const update = async () => {
    if (!cy) return;
    try {
      const data = await rqt.get('/api/tf/frames');
      render(data.frames, data.time);
    } catch (error) {
      note.textContent = `TF data unavailable: ${error.message}`;
    }
  };

  const download = (name, blob) => {
    const link = rqt.el('a', {href: URL.createObjectURL(blob), download: name});
    document.body.append(link);
    link.click();
    link.remove();
  };
  refresh.addEventListener('click', update);
  clear.addEventListener('click', async () => { await rqt.post('/api/tf/clear', {}); shownKey = ''; update(); });
  fit.addEventListener('click', () => cy && cy.fit(undefined, 20));
  exportPng.addEventListener('click', () => download('frames.png', cy.png({full: true, output: 'blob', bg: 'white'})));
  exportSvg.addEventListener('click', () => download('frames.svg', new Blob([cy.svg({full: true, bg: 'white'})], {type: 'image/svg+xml'})));

  (async () => {
    try {
      for (const name of ['cytoscape.min.js', 'cytoscape-dagre.js', 'cytoscape-svg.js']) await loadScript(`/vendor/${name}`);
    } catch (error) {
      box.replaceWith(rqt.el('p', {class: 'error', id: 'tf-unavailable', text:
        'TF Tree unavailable: its browser libraries (cytoscape, cytoscape-dagre) are not installed. Install npm and rerun scripts/setup.'}));
      return;
    }
    cy = cytoscape({
      container: box,
      style: [
        {selector: 'node', style: {label: 'data(label)', 'text-valign': 'center', 'font-size': 13, 'background-color': '#fff', 'border-width': 1.5, 'border-color': '#333', width: (ele) => 24 + 8 * ele.data('label').length, height: 34, shape: 'ellipse'}},
        {selector: 'node[kind="legend"]', style: {shape: 'rectangle', 'border-width': 2, 'border-color': '#000', 'font-size': 12}},
        {selector: 'edge', style: {'curve-style': 'bezier', 'target-arrow-shape': 'triangle', width: 1.5, 'line-color': '#555', 'target-arrow-color': '#555', label: 'data(label)', 'font-size': 10, 'text-wrap': 'wrap', 'text-background-color': '#fff', 'text-background-opacity': 0.85}},
        {selector: 'edge[kind="legend"]', style: {visibility: 'hidden'}},
      ],
    });
    window.rqtCy = cy;  // for the browser tests
    await update();
    setInterval(() => { if (auto.checked) update(); }, PERIOD_MS);
  })();
})();
