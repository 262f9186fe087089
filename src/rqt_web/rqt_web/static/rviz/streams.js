// PointCloud2, Image and Map: each new message once, as binary the server made with numpy
// (GET waits up to 1 s for one newer than `after`), fetched by a worker so that a busy main
// thread (rendering) costs one task per message; drawn at the next animation frame, the
// newest only.
import {setStatus} from './panel.js';
import {place} from './scene.js';
import {state} from './state.js';

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
let fetcherUrl = null;
const streams = [];

// Display `d`'s messages from /api/rviz/<kind>, drawn by draw(meta, body); info.received counts them.
export const streamLoop = (kind, d, draw, info) => {
  fetcherUrl ??= URL.createObjectURL(new Blob([FETCHER], {type: 'text/javascript'}));
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
    + `&reliability=${encodeURIComponent(d.reliability || 'Reliable')}`
    + (kind === 'map' ? `&scheme=${encodeURIComponent(mapScheme(d))}` : ''), location.href).href});
};

// A Map display's Color Scheme (map, costmap or raw; rviz's default: map).
export const mapScheme = (d) => String(d.settings?.['Color Scheme'] || 'map');

// At each animation frame: every stream's newest message since the last frame.
export const drawStreams = () => {
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

// A display's group placed in its message's frame, hidden (and the status saying why) without one.
export const frameStatus = (d, group, frame) => {
  const pose = state.frames[frame];
  group.visible = Boolean(pose && !pose.error);
  if (group.visible) place(group, pose);
  setStatus(d.name, group.visible ? 'OK' : `No transform from [${frame}] to [${state.fixedFrame}]`);
};
