// The displays of one message type (Pose, PoseArray, Path, Odometry, LaserScan) and Axes:
// every 100 ms, each topic's latest message (the server keeps it) drawn in its header's frame.
import * as THREE from 'three';

import {note, setStatus} from '../panel.js';
import {place} from '../scene.js';
import {state} from '../state.js';
import {addAxes} from './axes.js';
import {LaserScan} from './laser_scan.js';
import {Path} from './path.js';
import {Odometry, Pose, PoseArray} from './pose.js';

const KINDS = {Pose, PoseArray, Path, Odometry, LaserScan};

export function add(ctx) {
  const axesDisplays = addAxes(ctx);
  const topicDisplays = state.displays.filter((d) => d.enabled && KINDS[d.class.split('/').pop()]).map((d) => {
    const group = new THREE.Group();
    ctx.scene.add(group);
    return {d, group, kind: KINDS[d.class.split('/').pop()]};
  });
  const pollTopics = async () => {
    for (const a of axesDisplays) a.update();
    for (const t of topicDisplays) {
      const data = await rqt.get(`/api/rviz/latest?topic=${encodeURIComponent(t.d.topic || '')}&type=${t.kind.type}`);
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
      const holder = new THREE.Group();
      t.kind.draw(holder, data.msg);
      t.group.add(holder);
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
}
