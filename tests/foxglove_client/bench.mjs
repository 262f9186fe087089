// bench/foxglove.py's client: subscribes to every /turtleN/pose and /bench_stamp channel,
// counts pose messages in a window (all, and /turtle1/pose alone) and measures /bench_stamp latency (stamp -> receive).
// Usage: node bench.mjs URL SUBPROTOCOL WARMUP_S WINDOW_S; prints one JSON line at the end.
import { performance } from "node:perf_hooks";

import wsProtocol from "@foxglove/ws-protocol";
import WebSocket from "ws";

const { FoxgloveClient } = wsProtocol;
const [url, subprotocol, warmup, window] = process.argv.slice(2);
const client = new FoxgloveClient({ ws: new WebSocket(url, [subprotocol]) });
const kinds = new Map(); // subscription id -> "pose" | "stamp"
let counting = false;
let poses = 0;
let turtle1 = 0; // /turtle1/pose alone, next to `ros2 topic hz /turtle1/pose`
const latencies = [];
const nowNs = () => (performance.timeOrigin + performance.now()) * 1e6;

client.on("advertise", (channels) => {
  for (const c of channels) {
    if (c.topic === "/turtle1/pose") kinds.set(client.subscribe(c.id), "turtle1");
    else if (/^\/turtle\d+\/pose$/.test(c.topic)) kinds.set(client.subscribe(c.id), "pose");
    if (c.topic === "/bench_stamp") kinds.set(client.subscribe(c.id), "stamp");
  }
});
client.on("message", ({ subscriptionId, data }) => {
  if (!counting) return;
  const kind = kinds.get(subscriptionId);
  if (kind === "pose") poses += 1;
  else if (kind === "turtle1") { poses += 1; turtle1 += 1; }
  else if (kind === "stamp") {
    // builtin_interfaces/Time in CDR: 4-byte encapsulation header, int32 sec, uint32 nanosec.
    const view = new DataView(data.buffer, data.byteOffset, data.byteLength);
    const stampNs = view.getInt32(4, true) * 1e9 + view.getUint32(8, true);
    latencies.push((nowNs() - stampNs) / 1e6);
  }
});
setTimeout(() => { counting = true; }, Number(warmup) * 1000);
setTimeout(() => {
  counting = false;
  const topics = [...kinds.values()].filter((k) => k !== "stamp").length;
  process.stdout.write(JSON.stringify({ poses, turtle1, topics, latencies }) + "\n");
  client.close();
  setTimeout(() => process.exit(0), 100);
}, (Number(warmup) + Number(window)) * 1000);
