// TF: a worker asks the server for every frame's pose in the fixed frame, and their parents,
// in one request that waits (up to 1 s) for tf data newer than its last answer; at most one
// request in flight and one per animation frame. The main thread only applies the answer:
// here (software WebGL at 40 frames/s) a fetch's promise or a setTimeout on the main thread
// ran 45-65 ms late, a worker's message 15 ms (p50), which is what the model's lag was made of.
import {note} from './panel.js';
import {state} from './state.js';

// The displays placed in their frame at each answer, in the order they registered.
const hooks = [];
export const onTf = (hook) => { hooks.push(hook); };

const applyTf = (data) => {
  if (data.fixed_frame !== state.fixedFrame) return;  // asked before the Fixed Frame box changed
  state.frames = data.poses;
  for (const hook of hooks) hook(data);
  state.updated = performance.now();
};

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

// The worker; post it the fixed frame at each animation frame.
export function startTf() {
  const worker = new Worker(URL.createObjectURL(new Blob([TF_FETCHER], {type: 'text/javascript'})));
  worker.onmessage = ({data}) => {
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
  return worker;
}
