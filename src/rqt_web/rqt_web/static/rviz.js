'use strict';
// RViz: a 3D view of tf2 frames and the robot model, as rviz2 draws them (Z up, fixed frame
// at the origin). three.js (npm, served from /vendor) renders; the server gives the .rviz
// file (?config=), the robot description and every frame's pose in the fixed frame (tf_feed).
// window.rviz exposes the state for tests: frames, per-display status, model links, clouds
// and images received, markers drawn, the active tool and what the tools published.
(() => {
  const main = document.getElementById('main');
  const params = new URLSearchParams(location.search);
  const state = {fixedFrame: params.get('fixed_frame') || 'map', background: [48, 48, 48],
    displays: [], frames: {}, status: {}, links: [], ready: false, renders: 0, config: null,
    clouds: {}, images: {}, maps: {}, markers: [], meshes: [], tool: 'interact', published: []};
  window.rviz = state;

  const fixedInput = rqt.el('input', {id: 'rviz-fixed-frame', value: state.fixedFrame, size: 16});
  const list = rqt.el('ul', {id: 'rviz-displays'});
  const note = rqt.el('span', {id: 'rviz-note', class: 'keys'});
  const view = rqt.el('div', {id: 'rviz-view', style: 'width:100%;height:560px;position:relative'});
  // The tool belt: rviz2's default tools (Interact moves the camera).
  const TOOL_NAMES = {interact: 'Interact', initialpose: '2D Pose Estimate', goal: '2D Goal Pose',
    point: 'Publish Point'};
  const toolButtons = Object.entries(TOOL_NAMES).map(([key, text]) =>
    rqt.el('button', {id: `rviz-tool-${key}`, 'data-tool': key, text, class: key === 'interact' ? 'active' : ''}));
  const imagePanel = rqt.el('div', {id: 'rviz-images', class: 'row'});
  main.append(rqt.el('div', {class: 'row'}, rqt.el('label', {}, 'Fixed Frame ', fixedInput),
    rqt.el('button', {id: 'rviz-top', text: 'Top view'}),
    rqt.el('button', {id: 'rviz-save', text: 'Save Config As...'}), note),
  rqt.el('div', {class: 'row', id: 'rviz-tools'}, ...toolButtons), list, view, imagePanel);
  fixedInput.addEventListener('change', () => { state.fixedFrame = fixedInput.value.trim() || 'map'; });

  const map = document.createElement('script');
  map.type = 'importmap';
  map.textContent = JSON.stringify({imports: {three: '/vendor/three.module.js'}});
  document.head.append(map);

  const DEFAULT_DISPLAYS = [
    {class: 'rviz_default_plugins/Grid', name: 'Grid', enabled: true},
    {class: 'rviz_default_plugins/TF', name: 'TF', enabled: true},
    {class: 'rviz_default_plugins/RobotModel', name: 'RobotModel', enabled: true,
      topic: '/robot_description', alpha: 1}];

  const setStatus = (name, text) => {
    // Unchanged: no DOM write (each TF answer sets the TF and RobotModel statuses again, and
    // a write, even of the same text, makes the next frame redo style and layout).
    if (state.status[name] === text) return;
    state.status[name] = text;
    const item = document.querySelector(`#rviz-displays li[data-name="${CSS.escape(name)}"] .status`);
    if (item) item.textContent = text;
  };

  async function loadConfig() {
    const path = params.get('config');
    if (!path) return {fixed_frame: state.fixedFrame, background: state.background, displays: DEFAULT_DISPLAYS};
    try {
      return await rqt.get(`/api/rviz/config?path=${encodeURIComponent(path)}`);
    } catch (error) {
      note.textContent = String(error.message || error);
      return {fixed_frame: state.fixedFrame, background: state.background, displays: DEFAULT_DISPLAYS};
    }
  }

  async function start() {
    const THREE = await import('three');
    const {OrbitControls} = await import('/vendor/OrbitControls.js');
    const {STLLoader} = await import('/vendor/STLLoader.js');
    const config = await loadConfig();
    state.config = config;
    if (!params.get('fixed_frame')) state.fixedFrame = config.fixed_frame;
    fixedInput.value = state.fixedFrame;
    state.displays = config.displays;
    for (const d of state.displays) {
      list.append(rqt.el('li', {'data-name': d.name}, `${d.name} (${d.class.split('/').pop()}`
        + `${d.topic ? ' ' + d.topic : ''}): `, rqt.el('span', {class: 'status', text: d.enabled ? 'OK' : 'disabled'})));
    }
    // Colours as given (rviz's 0-255 background, URDF rgba), without sRGB conversion.
    THREE.ColorManagement.enabled = false;
    // Multisampling off when point clouds are shown: it does nothing for points and cost 2.4x
    // per frame with 100,000 of them in Chromium's software renderer (7 -> 17 frames/s).
    const clouds = state.displays.some((d) => d.enabled && d.class.endsWith('/PointCloud2'));
    // Off in a software renderer too (no GPU: SwiftShader, llvmpipe), where 4 samples a pixel
    // are 4 times the fragment work on the CPU: with r2d2 and 107 TF frames, 34 -> 48 frames/s
    // and the /joint_states-to-screen lag 55 -> 38 ms (p50), the CPU shared with ROS here.
    const software = (() => {
      const gl = document.createElement('canvas').getContext('webgl2') || document.createElement('canvas').getContext('webgl');
      if (!gl) return false;
      const info = gl.getExtension('WEBGL_debug_renderer_info');
      const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
      gl.getExtension('WEBGL_lose_context')?.loseContext();
      return /SwiftShader|llvmpipe|softpipe|software/i.test(name);
    })();
    state.antialias = !clouds && !software;
    const renderer = new THREE.WebGLRenderer({antialias: state.antialias, preserveDrawingBuffer: true});
    renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
    renderer.setSize(view.clientWidth, view.clientHeight);
    const [r, g, b] = config.background;
    renderer.setClearColor(new THREE.Color(r / 255, g / 255, b / 255));
    view.append(renderer.domElement);
    const scene = new THREE.Scene();
    scene.add(new THREE.AmbientLight(0xffffff, 0.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(3, 2, 6);
    scene.add(sun);
    const camera = new THREE.PerspectiveCamera(45, view.clientWidth / view.clientHeight, 0.01, 1000);
    camera.up.set(0, 0, 1);
    const v = config.view || {};
    const distance = Number(v.Distance) || 10, pitch = Number(v.Pitch ?? 0.785), yaw = Number(v.Yaw ?? 0.785);
    camera.position.set(distance * Math.cos(pitch) * Math.cos(yaw), distance * Math.cos(pitch) * Math.sin(yaw),
      distance * Math.sin(pitch));
    const controls = new OrbitControls(camera, renderer.domElement);
    controls.target.set(0, 0, 0);
    if (String(v.Class || '').endsWith('TopDownOrtho')) {
      // rviz's top-down view: Scale pixels per metre, centred on (X, Y). Seen from straight
      // above at the height where the 45-degree field shows the same metres.
      const scale = Number(v.Scale) || 10, x = Number(v.X) || 0, y = Number(v.Y) || 0;
      const height = (view.clientHeight / scale / 2) / Math.tan(Math.PI / 8);
      camera.position.set(x, y - 0.0001, height);
      controls.target.set(x, y, 0);
    }
    controls.update();
    document.getElementById('rviz-top').addEventListener('click', () => {
      camera.position.set(0, -0.0001, camera.position.length());
      controls.target.set(0, 0, 0);
      controls.update();
    });
    state.camera = camera;
    // Where a point of the fixed frame appears in the page (CSS pixels): for tests and bench.
    state.project = (x, y, z) => {
      const p = new THREE.Vector3(x, y, z).project(camera);
      const box = renderer.domElement.getBoundingClientRect();
      return [box.left + (p.x + 1) / 2 * box.width, box.top + (1 - p.y) / 2 * box.height];
    };

    // Save Config: the page's setup in upstream rviz2's .rviz YAML layout (keys and nesting
    // as rviz2 writes them: maps with sorted keys, lists of maps), downloaded as a file.
    const yamlScalar = (v) => {
      if (v === null || v === undefined) return '~';
      if (typeof v !== 'string') return String(v);
      // Quoted when YAML would read it as something else (a number, bool, null) or choke.
      const plain = v !== '' && !/^[\s\-?:,\[\]{}#&*!|>'"%@`]/.test(v) && !/(:\s|\s#|:$|\s$|[\n\t"])/.test(v)
        && !/^(true|false|yes|no|on|off|y|n|null|~)$/i.test(v) && !/^([-+]?[\d.][\d._:eE+-]*|[-+]?\.(inf|nan))$/i.test(v);
      return plain ? v : JSON.stringify(v);
    };
    const toYaml = (map, indent = 0) => {
      const pad = ' '.repeat(indent);
      const out = [];
      for (const key of Object.keys(map).sort()) {
        const v = map[key];
        if (Array.isArray(v)) {
          out.push(v.length ? `${pad}${key}:` : `${pad}${key}: []`);
          for (const item of v) {
            const inner = item && typeof item === 'object' ? toYaml(item, indent + 4) : [];
            if (inner.length) out.push(`${pad}  - ${inner[0].trimStart()}`, ...inner.slice(1));
            else out.push(`${pad}  - ${item && typeof item === 'object' ? '{}' : yamlScalar(item)}`);
          }
        } else if (v && typeof v === 'object') {
          out.push(...(Object.keys(v).length ? [`${pad}${key}:`, ...toYaml(v, indent + 2)] : [`${pad}${key}: {}`]));
        } else out.push(`${pad}${key}: ${yamlScalar(v)}`);
      }
      return out;
    };
    const DEFAULT_TOOLS = [['Interact'], ['MoveCamera'], ['Select'], ['FocusCamera'], ['Measure'],
      ['SetInitialPose', '/initialpose'], ['SetGoal', '/goal_pose'], ['PublishPoint', '/clicked_point']]
      .map(([name, topic]) => ({class: `rviz_default_plugins/${name}`, topic}));
    const round = (x) => Number(x.toFixed(6));
    state.saveConfig = () => {
      const displays = state.displays.map((d) => {
        const out = {...(d.settings || {}), Class: d.class, Enabled: d.enabled, Name: d.name, Value: d.enabled};
        const key = d.class.endsWith('/RobotModel') ? 'Description Topic' : 'Topic';
        const topic = out[key] && typeof out[key] === 'object' ? out[key] : {};  // QoS kept
        delete out.Topic;
        delete out['Description Topic'];
        if (d.topic) out[key] = {...topic, Value: d.topic};
        return out;
      });
      const tools = ((config.tools || []).length ? config.tools : DEFAULT_TOOLS).map((t) => (
        t.topic ? {Class: t.class, Topic: {Value: t.topic}} : {Class: t.class}));
      const offset = camera.position.clone().sub(controls.target);
      const distance = offset.length();
      const common = {Name: 'Current View', 'Near Clip Distance': 0.01, 'Target Frame': '<Fixed Frame>'};
      const current = String((config.view || {}).Class || '').endsWith('TopDownOrtho')
        ? {...common, Class: 'rviz_default_plugins/TopDownOrtho', Angle: 0, 'Invert Z Axis': false,
          // the height the page's 45-degree camera looks from, back to pixels per metre
          Scale: round(view.clientHeight / 2 / (offset.z * Math.tan(Math.PI / 8))),
          Value: 'TopDownOrtho (rviz_default_plugins)', X: round(controls.target.x), Y: round(controls.target.y)}
        : {...common, Class: 'rviz_default_plugins/Orbit', Distance: round(distance),
          'Focal Point': {X: round(controls.target.x), Y: round(controls.target.y), Z: round(controls.target.z)},
          Pitch: round(Math.asin(offset.z / distance)),
          Value: 'Orbit (rviz)', Yaw: round((Math.atan2(offset.y, offset.x) + 2 * Math.PI) % (2 * Math.PI))};
      const [br, bg, bb] = config.background;
      return toYaml({
        Panels: [
          {Class: 'rviz_common/Displays', 'Help Height': 78, Name: 'Displays',
            'Property Tree Widget': {Expanded: ['/Global Options1'], 'Splitter Ratio': 0.5}, 'Tree Height': 557},
          {Class: 'rviz_common/Views', Expanded: ['/Current View1'], Name: 'Views', 'Splitter Ratio': 0.5}],
        'Visualization Manager': {
          Class: '', Displays: displays, Enabled: true,
          'Global Options': {'Background Color': `${br}; ${bg}; ${bb}`, 'Fixed Frame': state.fixedFrame,
            'Frame Rate': 30},
          Name: 'root', Tools: tools, Transformation: {Current: {Class: 'rviz_default_plugins/TF'}},
          Value: true, Views: {Current: current, Saved: null}},
        'Window Geometry': {Displays: {collapsed: false}, Height: window.innerHeight, 'Hide Left Dock': false,
          'Hide Right Dock': false, Views: {collapsed: false}, Width: window.innerWidth, X: 0, Y: 0},
      }).join('\n') + '\n';
    };
    document.getElementById('rviz-save').addEventListener('click', () => {
      const link = rqt.el('a', {href: URL.createObjectURL(new Blob([state.saveConfig()], {type: 'text/yaml'})),
        download: (params.get('config') || 'config.rviz').split('/').pop()});
      link.click();
    });

    const enabled = (cls) => state.displays.filter((d) => d.enabled && d.class.endsWith(cls));
    // Grid: rviz's default, 10 cells of 1 m on the XY plane of the fixed frame.
    for (const d of enabled('/Grid')) {
      const cells = Number(d.settings?.['Plane Cell Count']) || 10;
      const size = (Number(d.settings?.['Cell Size']) || 1) * cells;
      const grid = new THREE.GridHelper(size, cells, 0xa0a0a4, 0xa0a0a4);
      grid.rotation.x = Math.PI / 2;
      scene.add(grid);
      setStatus(d.name, 'OK');
    }
    const tfDisplay = enabled('/TF')[0];
    const tfGroup = new THREE.Group();
    scene.add(tfGroup);
    const tfObjects = {};
    const label = (text) => {
      const canvas = document.createElement('canvas');
      canvas.width = 256; canvas.height = 48;
      const ctx = canvas.getContext('2d');
      ctx.font = '28px sans-serif'; ctx.fillStyle = '#ffffff'; ctx.fillText(text, 4, 34);
      const sprite = new THREE.Sprite(new THREE.SpriteMaterial({map: new THREE.CanvasTexture(canvas), depthTest: false}));
      sprite.scale.set(0.5, 0.094, 1);
      sprite.position.set(0, 0, 0.08);
      return sprite;
    };
    const tfFrame = (name) => {
      if (!tfObjects[name]) {
        const group = new THREE.Group();
        const scale = Number(tfDisplay?.settings?.['Marker Scale']) || 1;
        const axes = new THREE.AxesHelper(0.25 * scale);
        group.add(axes, label(name));
        tfGroup.add(group);
        tfObjects[name] = {group};
      }
      return tfObjects[name];
    };
    // Every frame's line to its parent, as segments of one object: one draw and one upload per
    // TF answer (a Line per frame was 107 of each, 43 -> 60 frames/s in software rendering).
    const tfLines = new THREE.LineSegments(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({color: 0xff66cc}));
    tfLines.frustumCulled = false;  // its extent changes with every answer
    tfGroup.add(tfLines);
    const setTfLines = (ends) => {
      let position = tfLines.geometry.getAttribute('position');
      if (!position || position.array.length < ends.length) {
        position = new THREE.BufferAttribute(new Float32Array(Math.max(ends.length, 64) * 2), 3);
        position.setUsage(THREE.DynamicDrawUsage);
        tfLines.geometry.setAttribute('position', position);
      }
      position.array.set(ends);
      position.needsUpdate = true;
      tfLines.geometry.setDrawRange(0, ends.length / 3);
    };

    // RobotModel: the URDF's visuals, each link placed where tf2 puts its frame.
    const robotDisplay = enabled('/RobotModel')[0];
    const robot = new THREE.Group();
    scene.add(robot);
    let modelCount = -1;
    const linkGroups = {};
    const stl = new STLLoader();
    const nums = (text, n) => {
      const values = (text || '').trim().split(/\s+/).filter((s) => s).map(Number);
      return values.length === n && values.every(Number.isFinite) ? values : Array(n).fill(0);
    };
    const resourceUrl = (uri) => `/api/rviz/resource?uri=${encodeURIComponent(uri)}`;
    // Mesh files, loaded once per URI: STL, DAE (three's ColladaLoader) and OBJ (OBJLoader).
    // Collada's up_axis is ignored as rviz does (assimp's IGNORE_UP_DIRECTION): three turns
    // Z_UP files to Y up, undone here; the unit scale is kept. A DAE's textures are fetched
    // next to it (resolved against its package:// or file:// URI).
    const meshCache = {};
    const loadMesh = (uri) => {
      meshCache[uri] ??= (async () => {
        const url = resourceUrl(uri);
        const ext = uri.toLowerCase().split('.').pop();
        if (ext === 'stl') return new THREE.Mesh(await stl.loadAsync(url), new THREE.MeshLambertMaterial());
        if (ext === 'dae') {
          const {ColladaLoader} = await import('/vendor/addons/loaders/ColladaLoader.js');
          const manager = new THREE.LoadingManager();
          const base = uri.slice(0, uri.lastIndexOf('/') + 1);
          manager.setURLModifier((u) => (u.startsWith('/api/rviz/') && !u.startsWith('/api/rviz/resource?')
            ? resourceUrl(base + u.slice('/api/rviz/'.length)) : u));
          const dae = await new ColladaLoader(manager).loadAsync(url);
          dae.scene.rotation.set(0, 0, 0);
          dae.scene.userData.embedded = true;  // the file's own materials
          return dae.scene;
        }
        if (ext === 'obj') {
          const {OBJLoader} = await import('/vendor/addons/loaders/OBJLoader.js');
          return new OBJLoader().loadAsync(url);
        }
        throw new Error('only STL, DAE and OBJ meshes are drawn');
      })();
      return meshCache[uri];
    };
    // A copy of a loaded mesh in `material`, or in its own materials when `own` and it has them.
    const meshInstance = (template, material, own) => {
      const copy = template.clone(true);
      if (!(own && template.userData.embedded)) copy.traverse((o) => { if (o.isMesh) o.material = material; });
      return copy;
    };
    const buildModel = (xml) => {
      robot.clear();
      for (const key of Object.keys(linkGroups)) delete linkGroups[key];
      const doc = new DOMParser().parseFromString(xml, 'application/xml');
      const root = doc.documentElement;
      if (!root || root.nodeName !== 'robot') {
        setStatus(robotDisplay.name, 'URDF: not a <robot> document');
        return;
      }
      const alpha = Number(robotDisplay.alpha ?? 1);
      const colours = {};
      for (const m of root.querySelectorAll(':scope > material')) {
        const c = m.querySelector('color');
        if (c) colours[m.getAttribute('name')] = nums(c.getAttribute('rgba'), 4);
      }
      const problems = [];
      for (const link of root.querySelectorAll(':scope > link')) {
        const name = link.getAttribute('name');
        const group = new THREE.Group();
        group.visible = false;
        linkGroups[name] = group;
        robot.add(group);
        for (const visual of link.querySelectorAll(':scope > visual')) {
          const geometry = visual.querySelector('geometry > *');
          if (!geometry) continue;
          const mat = visual.querySelector(':scope > material');
          let rgba = [0.8, 0.8, 0.8, 1];
          if (mat) {
            const c = mat.querySelector('color');
            rgba = c ? nums(c.getAttribute('rgba'), 4) : (colours[mat.getAttribute('name')] || rgba);
          }
          const material = new THREE.MeshLambertMaterial({color: new THREE.Color(rgba[0], rgba[1], rgba[2]),
            transparent: alpha * rgba[3] < 1, opacity: alpha * rgba[3]});
          const holder = new THREE.Group();
          const origin = visual.querySelector(':scope > origin');
          if (origin) {
            holder.position.set(...nums(origin.getAttribute('xyz'), 3));
            const [rr, pp, yy] = nums(origin.getAttribute('rpy'), 3);
            holder.rotation.set(rr, pp, yy, 'ZYX');
          }
          const kind = geometry.nodeName;
          if (kind === 'box') {
            holder.add(new THREE.Mesh(new THREE.BoxGeometry(...nums(geometry.getAttribute('size'), 3)), material));
          } else if (kind === 'cylinder') {
            const radius = Number(geometry.getAttribute('radius')), length = Number(geometry.getAttribute('length'));
            const mesh = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius, length, 32), material);
            mesh.rotation.x = Math.PI / 2;  // three's cylinders run along y, URDF's along z
            holder.add(mesh);
          } else if (kind === 'sphere') {
            holder.add(new THREE.Mesh(new THREE.SphereGeometry(Number(geometry.getAttribute('radius')), 32, 16), material));
          } else if (kind === 'mesh') {
            const uri = geometry.getAttribute('filename') || '';
            const scale = geometry.getAttribute('scale') ? nums(geometry.getAttribute('scale'), 3) : [1, 1, 1];
            // A URDF <material> colours the whole mesh; without one a DAE keeps its own (rviz).
            loadMesh(uri).then((template) => {
              const scaled = new THREE.Group();
              scaled.scale.set(...scale);
              scaled.add(meshInstance(template, material, !mat));
              holder.add(scaled);
              state.meshes.push({link: name, uri});
            }, (error) => setStatus(robotDisplay.name, `Could not load mesh ${uri} of link '${name}': ${error.message || error}`));
          }
          group.add(holder);
        }
      }
      setStatus(robotDisplay.name, problems.length ? problems[0] : 'OK');
      state.links = Object.keys(linkGroups);
    };
    const pollDescription = async () => {
      if (!robotDisplay) return;
      try {
        const d = await rqt.get(`/api/rviz/description?topic=${encodeURIComponent(robotDisplay.topic || '/robot_description')}`);
        if (d.count !== modelCount) {
          modelCount = d.count;
          if (d.urdf) buildModel(d.urdf);
          else setStatus(robotDisplay.name, `No robot description on ${d.topic}`);
        }
      } catch (error) {
        setStatus(robotDisplay.name, String(error.message || error));
      }
    };

    const afterTf = [];  // displays placed in their frame at each TF poll
    const place = (object, pose) => {
      object.position.set(...pose.translation);
      object.quaternion.set(...pose.rotation);
    };
    // TF: a worker asks the server for every frame's pose in the fixed frame, and their parents,
    // in one request that waits (up to 1 s) for tf data newer than its last answer; at most one
    // request in flight and one per animation frame. The main thread only applies the answer:
    // here (software WebGL at 40 frames/s) a fetch's promise or a setTimeout on the main thread
    // ran 45-65 ms late, a worker's message 15 ms (p50), which is what the model's lag was made of.
    const applyTf = (data) => {
      const fixed = data.fixed_frame;
      if (fixed !== state.fixedFrame) return;  // asked before the Fixed Frame box changed
      state.frames = data.poses;
      for (const [name, pose] of Object.entries(data.poses)) {
        if (tfDisplay && !pose.error) {
          const item = tfFrame(name);
          place(item.group, pose);
          item.group.visible = true;
        } else if (tfObjects[name]) {
          tfObjects[name].group.visible = false;
        }
      }
      if (tfDisplay) {
        const ends = [];
        for (const [child, parent] of Object.entries(data.parents)) {
          const c = data.poses[child], p = data.poses[parent];
          if (c && p && !c.error && !p.error) ends.push(...c.translation, ...p.translation);
        }
        setTfLines(ends);
        const names = Object.keys(data.poses).filter((n) => n !== fixed);
        setStatus(tfDisplay.name, names.length || data.poses[fixed] && !data.poses[fixed].error ? 'OK'
          : `Fixed Frame [${fixed}] does not exist`);
      }
      if (robotDisplay && state.links.length) {
        const missing = [];
        for (const [name, group] of Object.entries(linkGroups)) {
          const pose = data.poses[name];
          if (pose && !pose.error) {
            place(group, pose);
            group.visible = true;
          } else {
            group.visible = false;
            missing.push(name);
          }
        }
        if (missing.length) setStatus(robotDisplay.name, `No transform from [${missing[0]}] to [${fixed}]`);
        else if (state.status[robotDisplay.name]?.startsWith('No transform')) setStatus(robotDisplay.name, 'OK');
      }
      for (const hook of afterTf) hook();
      state.updated = performance.now();
    };

    // Marker and MarkerArray: the markers alive on each display's topic, in their frame.
    const markerDisplays = [...enabled('/Marker'), ...enabled('/MarkerArray')].map((d) => {
      const group = new THREE.Group();
      scene.add(group);
      return {d, group, type: d.class.endsWith('/MarkerArray') ? 'MarkerArray' : 'Marker'};
    });
    const colour = (c) => new THREE.Color(c[0], c[1], c[2]);
    const meshErrors = {};
    // Where a marker's frame was when it came (rviz transforms a marker once, unless it is
    // frame_locked: then it follows its frame). Keyed by display, ns, id; renewed per message.
    const frozen = {};
    const shapeMaterial = (c) => new THREE.MeshLambertMaterial({color: colour(c), transparent: c[3] < 1, opacity: c[3]});
    const markerObject = (m) => {
      const [sx, sy, sz] = m.scale;
      const pts = m.points.map((p) => new THREE.Vector3(...p));
      switch (m.type) {
        case 0: {  // ARROW: along x, scale = length, width, height
          const dir = new THREE.Vector3(1, 0, 0);
          return new THREE.ArrowHelper(dir, new THREE.Vector3(), sx, colour(m.color), 0.23 * sx, sy);
        }
        case 1: return new THREE.Mesh(new THREE.BoxGeometry(sx, sy, sz), shapeMaterial(m.color));
        case 2: {
          const mesh = new THREE.Mesh(new THREE.SphereGeometry(0.5, 24, 12), shapeMaterial(m.color));
          mesh.scale.set(sx, sy, sz);
          return mesh;
        }
        case 3: {
          const mesh = new THREE.Mesh(new THREE.CylinderGeometry(0.5, 0.5, 1, 24), shapeMaterial(m.color));
          mesh.scale.set(sx, sz, sy);
          mesh.rotation.x = Math.PI / 2;
          const holder = new THREE.Group();
          holder.add(mesh);
          return holder;
        }
        case 4: case 5: {  // LINE_STRIP, LINE_LIST
          const geo = new THREE.BufferGeometry().setFromPoints(pts);
          const mat = new THREE.LineBasicMaterial({color: colour(m.color)});
          return m.type === 4 ? new THREE.Line(geo, mat) : new THREE.LineSegments(geo, mat);
        }
        case 6: case 7: {  // CUBE_LIST, SPHERE_LIST
          const geo = m.type === 6 ? new THREE.BoxGeometry(sx, sy, sz) : new THREE.SphereGeometry(sx / 2, 16, 8);
          const holder = new THREE.Group();
          pts.forEach((p, i) => {
            const mesh = new THREE.Mesh(geo, shapeMaterial(m.colors[i] || m.color));
            mesh.position.copy(p);
            holder.add(mesh);
          });
          return holder;
        }
        case 8: {  // POINTS
          const geo = new THREE.BufferGeometry().setFromPoints(pts);
          return new THREE.Points(geo, new THREE.PointsMaterial({color: colour(m.color), size: sx}));
        }
        case 9: {  // TEXT_VIEW_FACING
          const sprite = label(m.text);
          sprite.scale.set(sz * 5.3, sz, 1);
          sprite.position.set(0, 0, 0);
          return sprite;
        }
        case 10: {  // MESH_RESOURCE: scale multiplies the mesh; its own materials if asked
          const holder = new THREE.Group();
          holder.scale.set(sx, sy, sz);
          loadMesh(m.mesh).then((template) => holder.add(meshInstance(template, shapeMaterial(m.color),
            m.embedded)), (error) => { meshErrors[m.mesh] = String(error.message || error); });
          return holder;
        }
        case 11: {  // TRIANGLE_LIST
          const geo = new THREE.BufferGeometry().setFromPoints(pts);
          geo.computeVertexNormals();
          const mat = shapeMaterial(m.color);
          mat.side = THREE.DoubleSide;
          return new THREE.Mesh(geo, mat);
        }
        default: return null;
      }
    };
    const pollMarkers = async () => {
      const drawn = [];
      for (const md of markerDisplays) {
        const data = await rqt.get(`/api/rviz/markers?topic=${encodeURIComponent(md.d.topic || '/visualization_marker')}&type=${md.type}`);
        md.group.clear();
        const problems = [];
        for (const m of data.markers) {
          const key = `${md.d.name}/${m.ns}/${m.id}`;
          let frame = state.frames[m.frame];
          if (!m.frame_locked && frozen[key]?.version === m.version) frame = frozen[key].pose;
          if (!frame || frame.error) {
            problems.push(`No transform from [${m.frame}] to [${state.fixedFrame}]`);
            continue;
          }
          if (!m.frame_locked) frozen[key] = {version: m.version, pose: frame};
          if (m.type === 10 && meshErrors[m.mesh]) {
            problems.push(`Could not load mesh ${m.mesh}: ${meshErrors[m.mesh]}`);
            continue;
          }
          const object = markerObject(m);
          if (!object) {
            problems.push(`marker ${m.ns}/${m.id}: type ${m.type} is not drawn`);
            continue;
          }
          const outer = new THREE.Group();
          place(outer, frame);
          const inner = new THREE.Group();
          inner.position.set(...m.position);
          inner.quaternion.set(...m.orientation);
          inner.add(object);
          outer.add(inner);
          md.group.add(outer);
          outer.updateMatrixWorld(true);
          const at = inner.getWorldPosition(new THREE.Vector3());
          drawn.push({display: md.d.name, ns: m.ns, id: m.id, type: m.type, position: [at.x, at.y, at.z]});
        }
        setStatus(md.d.name, problems.length ? problems[0] : `OK (${data.markers.length} markers)`);
      }
      state.markers = drawn;
    };
    const tickMarkers = async () => {
      try {
        await pollMarkers();
      } catch (error) {
        note.textContent = String(error.message || error);
      }
      setTimeout(tickMarkers, 100);
    };
    if (markerDisplays.length) tickMarkers();

    // Axes, and the displays of one message type: Pose, PoseArray, Path, Odometry, LaserScan.
    const axesDisplays = enabled('/Axes').map((d) => {
      const length = Number(d.settings?.Length) || 1;
      const axes = new THREE.AxesHelper(length);
      scene.add(axes);
      return {d, axes, frame: d.settings?.['Reference Frame'] || '<Fixed Frame>'};
    });
    const TYPES = {Pose: 'geometry_msgs/msg/PoseStamped', PoseArray: 'geometry_msgs/msg/PoseArray',
      Path: 'nav_msgs/msg/Path', Odometry: 'nav_msgs/msg/Odometry', LaserScan: 'sensor_msgs/msg/LaserScan'};
    const topicDisplays = state.displays.filter((d) => d.enabled && TYPES[d.class.split('/').pop()]).map((d) => {
      const group = new THREE.Group();
      scene.add(group);
      return {d, group, kind: d.class.split('/').pop()};
    });
    const arrow = (pose, hex) => {
      const o = new THREE.Group();
      o.position.set(pose.position.x, pose.position.y, pose.position.z);
      const q = pose.orientation;
      o.quaternion.set(q.x, q.y, q.z, q.w);
      o.add(new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1, hex, 0.3, 0.1));
      return o;
    };
    const drawMessage = (kind, msg) => {
      const holder = new THREE.Group();
      if (kind === 'Pose') holder.add(arrow(msg.pose, 0xff1919));
      if (kind === 'Odometry') holder.add(arrow(msg.pose.pose, 0xff1919));
      if (kind === 'PoseArray') for (const pose of msg.poses) holder.add(arrow(pose, 0xff1919));
      if (kind === 'Path') {
        const points = msg.poses.map((p) => new THREE.Vector3(p.pose.position.x, p.pose.position.y, p.pose.position.z));
        holder.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(points),
          new THREE.LineBasicMaterial({color: 0x19ff00})));
      }
      if (kind === 'LaserScan') {
        const points = [];
        msg.ranges.forEach((r, i) => {
          if (!(r >= msg.range_min && r <= msg.range_max)) return;
          const a = msg.angle_min + i * msg.angle_increment;
          points.push(new THREE.Vector3(r * Math.cos(a), r * Math.sin(a), 0));
        });
        holder.add(new THREE.Points(new THREE.BufferGeometry().setFromPoints(points),
          new THREE.PointsMaterial({color: 0xffffff, size: 0.05})));
      }
      return holder;
    };
    const pollTopics = async () => {
      for (const a of axesDisplays) {
        const frame = a.frame === '<Fixed Frame>' ? state.fixedFrame : a.frame;
        const pose = state.frames[frame];
        a.axes.visible = Boolean(pose && !pose.error);
        if (a.axes.visible) place(a.axes, pose);
        setStatus(a.d.name, a.axes.visible ? 'OK' : `No transform from [${frame}] to [${state.fixedFrame}]`);
      }
      for (const t of topicDisplays) {
        const data = await rqt.get(`/api/rviz/latest?topic=${encodeURIComponent(t.d.topic || '')}&type=${TYPES[t.kind]}`);
        t.group.clear();
        if (!data.msg) {
          setStatus(t.d.name, `No messages received on ${t.d.topic}`);
          continue;
        }
        const frameId = data.msg.header.frame_id;
        const pose = state.frames[frameId];
        if (!pose || pose.error) {
          setStatus(t.d.name, `No transform from [${frameId}] to [${state.fixedFrame}]`);
          continue;
        }
        place(t.group, pose);
        t.group.add(drawMessage(t.kind, data.msg));
        setStatus(t.d.name, 'OK');
      }
    };
    const tickTopics = async () => {
      try {
        await pollTopics();
      } catch (error) {
        note.textContent = String(error.message || error);
      }
      setTimeout(tickTopics, 100);
    };
    if (axesDisplays.length || topicDisplays.length) tickTopics();

    // PointCloud2 and Image: each new message once, as binary the server made with numpy
    // (GET waits up to 1 s for one newer than `after`), fetched by a worker so that a busy
    // main thread (rendering) costs one task per message; drawn at the next animation frame,
    // the newest only.
    const FETCHER = `self.onmessage = async ({data: {url}}) => {
      let after = 0;
      for (;;) {
        try {
          const response = await fetch(url + '&after=' + after, {credentials: 'same-origin'});
          if (!response.ok) throw new Error(await response.text());
          const meta = JSON.parse(response.headers.get('X-Rviz') || '{}');
          if (response.status === 204) {
            if (!meta.seq) self.postMessage({meta, body: null});
            continue;
          }
          after = meta.seq;
          const body = await response.arrayBuffer();
          self.postMessage({meta, body}, [body]);
        } catch (error) {
          self.postMessage({error: String(error.message || error)});
          await new Promise((resolve) => { setTimeout(resolve, 1000); });
        }
      }
    };`;
    const fetcherUrl = URL.createObjectURL(new Blob([FETCHER], {type: 'text/javascript'}));
    const streams = [];
    const streamLoop = (kind, d, draw, info) => {
      const stream = {latest: null, draw, d};
      streams.push(stream);
      const worker = new Worker(fetcherUrl);
      worker.onmessage = ({data}) => {
        if (data.error) setStatus(d.name, data.error);
        else if (!data.body) setStatus(d.name, `No messages received on ${d.topic}`);
        else if (data.meta.error) setStatus(d.name, data.meta.error);
        else {
          info.received += 1;
          stream.latest = data;
        }
      };
      worker.postMessage({url: new URL(`/api/rviz/${kind}?topic=${encodeURIComponent(d.topic || '')}`
        + `&reliability=${encodeURIComponent(d.reliability || 'Reliable')}`, location.href).href});
    };
    const drawStreams = () => {
      for (const stream of streams) {
        if (!stream.latest) continue;
        const {meta, body} = stream.latest;
        stream.latest = null;
        try {
          stream.draw(meta, body);
        } catch (error) {
          setStatus(stream.d.name, String(error.message || error));
        }
      }
    };
    const frameStatus = (d, group, frame) => {
      const pose = state.frames[frame];
      group.visible = Boolean(pose && !pose.error);
      if (group.visible) place(group, pose);
      setStatus(d.name, group.visible ? 'OK' : `No transform from [${frame}] to [${state.fixedFrame}]`);
    };
    // PointCloud2: THREE.Points of the finite points, coloured as the server's RGB8 or
    // Intensity transformer gave them (or the display's FlatColor); Size (m) as flat squares,
    // Style Points as Size (Pixels).
    for (const d of enabled('/PointCloud2')) {
      const s = d.settings || {};
      const pixels = s.Style === 'Points';
      const size = pixels ? Number(s['Size (Pixels)']) || 3 : Number(s['Size (m)']) || 0.01;
      const flat = s['Color Transformer'] === 'FlatColor';
      const flatColour = new THREE.Color(...String(s.Color || '255; 255; 255').split(';').map((v) => Number(v) / 255));
      const alpha = Number(d.alpha ?? 1);
      const group = new THREE.Group();
      scene.add(group);
      const info = {received: 0, drawn: 0, points: 0, frame: null, seq: 0, color: null};
      state.clouds[d.name] = info;
      let points = null;
      streamLoop('cloud', d, (meta, body) => {
        const geo = new THREE.BufferGeometry();
        geo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(body, 0, meta.points * 3), 3));
        const coloured = Boolean(meta.color) && !flat;
        if (coloured) {
          geo.setAttribute('color', new THREE.BufferAttribute(new Uint8Array(body, meta.points * 12, meta.points * 3), 3, true));
        }
        const material = new THREE.PointsMaterial({size, sizeAttenuation: !pixels, vertexColors: coloured,
          color: coloured ? 0xffffff : flatColour, transparent: alpha < 1, opacity: alpha});
        if (points) {
          group.remove(points);
          points.geometry.dispose();
          points.material.dispose();
        }
        points = new THREE.Points(geo, material);
        points.frustumCulled = false;  // no bounding sphere over every point of every cloud
        group.add(points);
        Object.assign(info, {drawn: info.drawn + 1, points: meta.points, frame: meta.frame,
          seq: meta.seq, color: meta.color});
        frameStatus(d, group, meta.frame);
      }, info);
      afterTf.push(() => { if (info.frame !== null) frameStatus(d, group, info.frame); });
    }
    // Image: a panel under the view per display, the image on a canvas of its size, shown
    // 320 px wide (rviz scales it to its panel, keeping the aspect ratio).
    for (const d of enabled('/Image')) {
      const canvas = rqt.el('canvas', {class: 'rviz-image', 'data-name': d.name, width: 1, height: 1,
        style: 'width:320px;height:auto;image-rendering:pixelated;background:#000'});
      imagePanel.append(rqt.el('figure', {style: 'margin:4px'}, rqt.el('figcaption', {text: `${d.name} ${d.topic || ''}`}), canvas));
      const ctx = canvas.getContext('2d');
      const info = {received: 0, drawn: 0, width: 0, height: 0, encoding: null, seq: 0};
      state.images[d.name] = info;
      streamLoop('image', d, (meta, body) => {
        if (canvas.width !== meta.width || canvas.height !== meta.height) {
          canvas.width = meta.width;
          canvas.height = meta.height;
        }
        if (meta.width && meta.height) {
          ctx.putImageData(new ImageData(new Uint8ClampedArray(body), meta.width, meta.height), 0, 0);
        }
        Object.assign(info, {drawn: info.drawn + 1, width: meta.width, height: meta.height,
          encoding: meta.encoding, seq: meta.seq});
        setStatus(d.name, 'OK');
      }, info);
    }

    // Map: the grid as a texture on a plane in the map's frame, cell (0, 0) at the origin's
    // corner and rows along +y, drawn with the display's Alpha (rviz: 0.7) below the robot.
    for (const d of enabled('/Map')) {
      const alpha = Number(d.alpha ?? 0.7);
      const group = new THREE.Group();
      scene.add(group);
      const info = {received: 0, drawn: 0, width: 0, height: 0, resolution: 0, frame: null, seq: 0};
      state.maps[d.name] = info;
      let holder = null;
      streamLoop('map', d, (meta, body) => {
        const texture = new THREE.DataTexture(new Uint8Array(body), meta.width, meta.height, THREE.RGBAFormat);
        texture.magFilter = THREE.NearestFilter;
        texture.needsUpdate = true;
        const w = meta.width * meta.resolution, h = meta.height * meta.resolution;
        const plane = new THREE.Mesh(new THREE.PlaneGeometry(w, h), new THREE.MeshBasicMaterial({
          map: texture, side: THREE.DoubleSide, transparent: alpha < 1, opacity: alpha, depthWrite: alpha >= 1}));
        plane.position.set(w / 2, h / 2, 0);
        if (holder) {
          group.remove(holder);
          holder.children[0].geometry.dispose();
          holder.children[0].material.map.dispose();
          holder.children[0].material.dispose();
        }
        holder = new THREE.Group();
        holder.position.set(...meta.position);
        holder.quaternion.set(...meta.orientation);
        holder.add(plane);
        group.add(holder);
        Object.assign(info, {drawn: info.drawn + 1, width: meta.width, height: meta.height,
          resolution: meta.resolution, frame: meta.frame, seq: meta.seq});
        frameStatus(d, group, meta.frame);
      }, info);
      afterTf.push(() => { if (info.frame !== null) frameStatus(d, group, info.frame); });
    }

    // The tool belt. 2D Pose Estimate and 2D Goal Pose: press on the ground plane (the fixed
    // frame's XY plane) for the position, drag for the orientation, release to publish.
    // Publish Point: a click publishes the point of the robot or a marker under the mouse,
    // else of the ground plane. Then back to Interact, as rviz2 does. Topics as rviz2's
    // (or the .rviz file's Tools).
    const TOOL_CLASSES = {initialpose: 'SetInitialPose', goal: 'SetGoal', point: 'PublishPoint'};
    const toolTopic = (tool) => (config.tools || []).find((t) => t.class.endsWith(`/${TOOL_CLASSES[tool]}`))?.topic;
    const setTool = (tool) => {
      state.tool = tool;
      controls.enabled = tool === 'interact';
      for (const b of toolButtons) b.classList.toggle('active', b.dataset.tool === tool);
    };
    for (const b of toolButtons) b.addEventListener('click', () => setTool(b.dataset.tool));
    const raycaster = new THREE.Raycaster();
    const ground = new THREE.Plane(new THREE.Vector3(0, 0, 1), 0);
    const aim = (event) => {
      const box = renderer.domElement.getBoundingClientRect();
      raycaster.setFromCamera(new THREE.Vector2((event.clientX - box.left) / box.width * 2 - 1,
        1 - (event.clientY - box.top) / box.height * 2), camera);
    };
    const groundPoint = (event) => {
      aim(event);
      return raycaster.ray.intersectPlane(ground, new THREE.Vector3());
    };
    const toolArrow = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1, 0x19ff00, 0.3, 0.1);
    toolArrow.visible = false;
    scene.add(toolArrow);
    const publishTool = async (tool, at, yaw) => {
      const body = {tool, frame: state.fixedFrame, x: at.x, y: at.y, z: at.z, yaw, topic: toolTopic(tool)};
      try {
        const answer = await rqt.post('/api/rviz/tool', body);
        state.published.push({...body, topic: answer.topic});
        note.textContent = `${TOOL_NAMES[tool]}: published on ${answer.topic}`;
      } catch (error) {
        note.textContent = `${TOOL_NAMES[tool]}: ${error.message || error}`;
      }
    };
    let pressed = null;
    const canvas = renderer.domElement;
    canvas.addEventListener('pointerdown', (event) => {
      if (state.tool === 'interact' || event.button !== 0) return;
      if (state.tool === 'point') {
        aim(event);
        const hit = raycaster.intersectObjects([robot, ...markerDisplays.map((md) => md.group)], true)
          .find((h) => h.object.isMesh);
        const at = hit ? hit.point : groundPoint(event);
        if (at) publishTool('point', at, 0);
        setTool('interact');
        return;
      }
      const at = groundPoint(event);
      if (!at) return;
      pressed = at;
      toolArrow.position.copy(at);
      toolArrow.setDirection(new THREE.Vector3(1, 0, 0));
      toolArrow.visible = true;
      canvas.setPointerCapture(event.pointerId);
    });
    canvas.addEventListener('pointermove', (event) => {
      const at = pressed && groundPoint(event);
      if (at && at.distanceTo(pressed) > 1e-6) toolArrow.setDirection(at.clone().sub(pressed).normalize());
    });
    canvas.addEventListener('pointerup', (event) => {
      if (!pressed) return;
      const at = groundPoint(event);
      const yaw = at && at.distanceTo(pressed) > 1e-6 ? Math.atan2(at.y - pressed.y, at.x - pressed.x) : 0;
      publishTool(state.tool, new THREE.Vector3(pressed.x, pressed.y, 0), yaw);
      pressed = null;
      toolArrow.visible = false;
      setTool('interact');
    });

    // The worker gets the fixed frame at each animation frame (the tick that allows its next
    // request); a changed one cancels the request in flight. Without frames (a hidden page) it
    // asks once a second.
    const TF_FETCHER = `const base = new URL('/api/tf/poses', self.location.href.replace(/^blob:/, '')).href;
      // after = -1: the first answer (and the first after a new fixed frame) comes at once.
      let fixed = null, after = -1, ticked = false, wake = null, controller = null;
      self.onmessage = ({data}) => {
        if (data !== fixed) {
          if (controller && fixed !== null) controller.abort();
          fixed = data;
          after = -1;
        }
        ticked = true;
        if (wake) wake();
        else if (!controller) loop();
      };
      const loop = async () => {
        for (;;) {
          if (!ticked) await new Promise((resolve) => { wake = resolve; setTimeout(resolve, 1000); });
          wake = null;
          ticked = false;
          const asked = fixed;
          controller = new AbortController();
          try {
            const response = await fetch(base + '?fixed_frame=' + encodeURIComponent(asked) + '&after=' + after,
              {credentials: 'same-origin', signal: controller.signal});
            if (!response.ok) throw new Error(await response.text());
            const data = await response.json();
            if (asked !== fixed) continue;
            after = data.version;
            self.postMessage({data});
          } catch (error) {
            if (asked !== fixed) continue;
            self.postMessage({error: String(error.message || error)});
            await new Promise((resolve) => { setTimeout(resolve, 1000); });
          }
        }
      };`;
    const tfWorker = new Worker(URL.createObjectURL(new Blob([TF_FETCHER], {type: 'text/javascript'})));
    tfWorker.onmessage = ({data}) => {
      if (data.error) {
        note.textContent = data.error;
        return;
      }
      try {
        applyTf(data.data);
      } catch (error) {
        note.textContent = String(error.message || error);
      }
    };
    setInterval(pollDescription, 1000);
    await pollDescription();
    const render = () => {
      tfWorker.postMessage(state.fixedFrame);
      drawStreams();
      controls.update();
      renderer.render(scene, camera);
      state.renders += 1;
      requestAnimationFrame(render);
    };
    render();
    state.ready = true;
  }
  start().catch((error) => { note.textContent = `RViz could not start: ${error.message || error}`; });
})();
