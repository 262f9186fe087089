'use strict';
// Node Graph, as rqt_graph: nodes and topics (and actions), live, laid out by dagre and
// drawn by cytoscape (both from the npm registry, installed by scripts/setup).
(() => {
  const main = document.getElementById('main');
  const mode = rqt.el('select', {id: 'mode'},
    rqt.el('option', {value: 'nodes', text: 'Nodes only'}),
    rqt.el('option', {value: 'active', text: 'Nodes/Topics (active)', selected: true}),
    rqt.el('option', {value: 'all', text: 'Nodes/Topics (all)'}));
  const checkbox = (id, text, checked) => {
    const box = rqt.el('input', {type: 'checkbox', id});
    box.checked = checked;
    return [box, rqt.el('label', {}, box, ` ${text}`)];
  };
  const [hideDebug, hideDebugLabel] = checkbox('hide-debug', 'Hide debug', true);
  const [hideDead, hideDeadLabel] = checkbox('hide-dead-sinks', 'Dead sinks', true);
  const [hideLeaf, hideLeafLabel] = checkbox('hide-leaf-topics', 'Leaf topics', true);
  const [showActions, showActionsLabel] = checkbox('show-actions', 'Actions', true);
  const filter = rqt.el('input', {type: 'text', id: 'filter', placeholder: 'filter: /turtle, -/rosout', size: 24});
  const exportSvg = rqt.el('button', {id: 'export-svg', text: 'Export SVG'});
  const exportPng = rqt.el('button', {id: 'export-png', text: 'Export PNG'});
  const note = rqt.el('span', {id: 'graph-note', class: 'keys'});
  const box = rqt.el('div', {id: 'cy'});
  const details = rqt.el('pre', {id: 'node-details'});
  main.append(rqt.el('div', {class: 'row'}, mode, hideDebugLabel, rqt.el('span', {text: 'Hide:'}),
    hideDeadLabel, hideLeafLabel, showActionsLabel, filter, exportSvg, exportPng, note), box,
  rqt.el('p', {class: 'keys', text: 'Click a node for its topics, services and actions.'}), details);

  // What a node offers, as `ros2 node info` lists it (services are not drawn, as in rqt_graph).
  const describeNode = (name) => {
    const node = graph && graph.nodes.find((n) => n.name === name);
    if (!node) return '';
    const section = (title, pairs) => `  ${title}:\n${pairs.map(([n, t]) => `    ${n}: ${t.join(', ')}`).join('\n')}`;
    return [name, section('Subscribers', node.subs), section('Publishers', node.pubs),
      section('Service Servers', node.services), section('Action Servers', node.action_servers),
      section('Action Clients', node.action_clients)].join('\n');
  };

  const DEBUG_TOPICS = new Set(['/rosout', '/rosout_agg', '/parameter_events', '/clock', '/statistics', '/diagnostics', '/diagnostics_agg']);
  let cy = null;
  let graph = null;
  let shownKey = '';

  const loadScript = (src) => new Promise((resolve, reject) => {
    const script = rqt.el('script', {src});
    script.onload = resolve;
    script.onerror = () => reject(new Error(src));
    document.head.append(script);
  });

  const matches = (name) => {
    const terms = filter.value.split(',').map((t) => t.trim()).filter(Boolean);
    const include = terms.filter((t) => !t.startsWith('-'));
    const exclude = terms.filter((t) => t.startsWith('-')).map((t) => t.slice(1));
    if (exclude.some((t) => name.includes(t))) return false;
    return include.length === 0 || include.some((t) => name.includes(t));
  };

  // The elements rqt_graph would draw for this graph and these options.
  const elements = (data) => {
    const nodes = data.nodes.filter((n) => matches(n.name) && !(hideDebug.checked && rqt.hidden(n.name)));
    const topics = new Map();
    const endpoint = (name) => { if (!topics.has(name)) topics.set(name, {pubs: [], subs: []}); return topics.get(name); };
    for (const node of nodes) {
      for (const [name] of node.pubs) endpoint(name).pubs.push(node.name);
      for (const [name] of node.subs) endpoint(name).subs.push(node.name);
    }
    const shownTopics = [...topics.entries()].filter(([name, ends]) => {
      if (rqt.hidden(name)) return false;  // hidden topics (action internals, _canvas)
      if (hideDebug.checked && DEBUG_TOPICS.has(name)) return false;
      if (mode.value !== 'all' && (ends.pubs.length === 0 || ends.subs.length === 0)) return false;
      if (hideDead.checked && ends.subs.length === 0) return false;
      if (hideLeaf.checked && ends.pubs.length + ends.subs.length <= 1) return false;
      return true;
    });
    const items = nodes.map((n) => ({data: {id: `n:${n.name}`, label: n.name, kind: 'node'}}));
    if (mode.value === 'nodes') {
      const edges = new Map();
      for (const [name, ends] of shownTopics) {
        for (const pub of ends.pubs) for (const sub of ends.subs) {
          const key = `${pub}->${sub}`;
          edges.set(key, [...(edges.get(key) || []), name]);
        }
      }
      for (const [key, names] of edges) {
        const [pub, sub] = key.split('->');
        items.push({data: {id: `e:${key}`, source: `n:${pub}`, target: `n:${sub}`, label: names.join('\n')}});
      }
    } else {
      for (const [name, ends] of shownTopics) {
        items.push({data: {id: `t:${name}`, label: name, kind: 'topic'}});
        for (const pub of ends.pubs) items.push({data: {id: `e:${pub}>${name}`, source: `n:${pub}`, target: `t:${name}`}});
        for (const sub of ends.subs) items.push({data: {id: `e:${name}>${sub}`, source: `t:${name}`, target: `n:${sub}`}});
      }
    }
    if (showActions.checked && mode.value !== 'nodes') {
      const actions = new Map();
      for (const node of nodes) {
        for (const [name] of node.action_servers) (actions.get(name) || actions.set(name, {servers: [], clients: []}).get(name)).servers.push(node.name);
        for (const [name] of node.action_clients) (actions.get(name) || actions.set(name, {servers: [], clients: []}).get(name)).clients.push(node.name);
      }
      for (const [name, ends] of actions) {
        if (hideLeaf.checked && ends.servers.length + ends.clients.length <= 1) continue;
        items.push({data: {id: `a:${name}`, label: `${name} (action)`, kind: 'action'}});
        for (const client of ends.clients) items.push({data: {id: `e:${client}>a:${name}`, source: `n:${client}`, target: `a:${name}`}});
        for (const server of ends.servers) items.push({data: {id: `e:a:${name}>${server}`, source: `a:${name}`, target: `n:${server}`}});
      }
    }
    return items;
  };

  const render = () => {
    if (!cy || !graph) return;
    const items = elements(graph);
    const key = JSON.stringify(items);
    if (key === shownKey) return;
    shownKey = key;
    cy.elements().remove();
    cy.add(items);
    cy.layout({name: 'dagre', rankDir: 'LR', nodeSep: 20, rankSep: 60}).run();
    cy.fit(undefined, 20);
    window.rqtGraph = {
      nodes: cy.nodes().map((n) => n.data('label')),
      edges: cy.edges().map((e) => [e.source().data('label'), e.target().data('label'), e.data('label') || '']),
      updated: Date.now(),
    };
  };

  const download = (name, blob) => {
    const link = rqt.el('a', {href: URL.createObjectURL(blob), download: name});
    document.body.append(link);
    link.click();
    link.remove();
  };
  exportPng.addEventListener('click', () => download('rosgraph.png', cy.png({full: true, output: 'blob', bg: 'white'})));
  exportSvg.addEventListener('click', () => download('rosgraph.svg', new Blob([cy.svg({full: true, bg: 'white'})], {type: 'image/svg+xml'})));
  for (const control of [mode, hideDebug, hideDead, hideLeaf, showActions]) control.addEventListener('change', render);
  filter.addEventListener('input', render);

  (async () => {
    try {
      for (const name of ['cytoscape.min.js', 'cytoscape-dagre.js', 'cytoscape-svg.js']) await loadScript(`/vendor/${name}`);
    } catch (error) {
      box.replaceWith(rqt.el('p', {class: 'error', id: 'graph-unavailable', text:
        'Node Graph unavailable: its browser libraries (cytoscape, cytoscape-dagre) are not installed. Install npm and rerun scripts/setup.'}));
      return;
    }
    cy = cytoscape({
      container: box,
      style: [
        {selector: 'node', style: {label: 'data(label)', 'text-valign': 'center', 'font-size': 12, 'background-color': '#fff', 'border-width': 1.5, 'border-color': '#333', width: (ele) => 16 + 7 * ele.data('label').length, height: 30, shape: 'ellipse'}},
        {selector: 'node[kind="topic"]', style: {shape: 'rectangle', 'border-color': '#1f5fa8'}},
        {selector: 'node[kind="action"]', style: {shape: 'round-rectangle', 'border-color': '#8a3ab9', 'border-style': 'dashed'}},
        {selector: 'edge', style: {'curve-style': 'bezier', 'target-arrow-shape': 'triangle', width: 1.5, 'line-color': '#555', 'target-arrow-color': '#555', label: 'data(label)', 'font-size': 10, 'text-wrap': 'wrap'}},
      ],
    });
    window.rqtCy = cy;  // for the browser tests
    cy.on('tap', 'node[kind="node"]', (event) => { details.textContent = describeNode(event.target.data('label')); });
    render();
  })();

  rqt.on('graph', (message) => {
    graph = message.graph;
    note.textContent = `${graph.nodes.length} nodes, ${graph.topics.length} topics`;
    render();
  });
  rqt.onOpen.push(() => rqt.send({op: 'graph'}));
})();
