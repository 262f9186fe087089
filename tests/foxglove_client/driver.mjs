// A Foxglove WebSocket client for the tests: @foxglove/ws-protocol's FoxgloveClient on `ws`,
// CDR through @foxglove/rosmsg2-serialization with the schema the server advertised.
// Usage: node driver.mjs URL SUBPROTOCOL[,SUBPROTOCOL...] (a list offers them all, as Lichtblick
// does). Reads one JSON command per line on stdin, writes one JSON event per line on stdout (every server event, plus each command's answer).
import { createInterface } from "node:readline";

import { parse as parseMessageDefinition } from "@foxglove/rosmsg";
import { MessageReader, MessageWriter } from "@foxglove/rosmsg2-serialization";
import wsProtocol from "@foxglove/ws-protocol";
import WebSocket from "ws";

const { FoxgloveClient } = wsProtocol;
const [url, subprotocol] = process.argv.slice(2);
const ws = new WebSocket(url, subprotocol.split(","));  // "a,b": offer both, as Lichtblick
const client = new FoxgloveClient({ ws });
const channels = new Map(); // id -> channel
const services = new Map(); // name -> service
const readers = new Map(); // subscription id -> {topic, reader}
const writers = new Map(); // client channel id -> writer
let nextCallId = 1;

const out = (event) => process.stdout.write(JSON.stringify(event) + "\n");
const definitions = (schema) => parseMessageDefinition(schema, { ros2: true });
const replacer = (_key, value) => (typeof value === "bigint" ? Number(value) : value);
const plain = (value) => JSON.parse(JSON.stringify(value, replacer));

ws.on("unexpected-response", (_req, res) => out({ event: "refused", status: res.statusCode }));
client.on("open", () => out({ event: "open", protocol: ws.protocol }));
client.on("close", (e) => out({ event: "close", code: e.code }));
client.on("error", (e) => out({ event: "error", message: String(e?.message ?? e) }));
client.on("serverInfo", (info) => out({ event: "serverInfo", info }));
client.on("status", (s) => out({ event: "status", level: s.level, message: s.message }));
client.on("advertise", (list) => {
  for (const c of list) channels.set(c.id, c);
  out({ event: "advertise", channels: list.map((c) => ({ id: c.id, topic: c.topic,
    encoding: c.encoding, schemaName: c.schemaName, schemaEncoding: c.schemaEncoding,
    schema: c.schema })) });
});
client.on("unadvertise", (ids) => { for (const id of ids) channels.delete(id); });
client.on("advertiseServices", (list) => {
  for (const s of list) services.set(s.name, s);
  out({ event: "advertiseServices", names: list.map((s) => s.name) });
});
client.on("message", ({ subscriptionId, timestamp, data }) => {
  const entry = readers.get(subscriptionId);
  if (!entry) return;
  const message = entry.reader.readMessage(new Uint8Array(data.buffer, data.byteOffset,
    data.byteLength));
  out({ event: "message", topic: entry.topic, receivedNs: Date.now() * 1e6,
    timestamp: Number(timestamp), message: plain(message) });
});
client.on("time", (t) => out({ event: "time", timestamp: Number(t.timestamp) }));
client.on("parameterValues", (p) => out({ event: "parameterValues", id: p.id,
  parameters: p.parameters }));
client.on("serviceCallResponse", (r) => {
  const service = [...services.values()].find((s) => s.id === r.serviceId);
  const schema = service.response?.schema ?? service.responseSchema;
  const reader = new MessageReader(definitions(schema));
  out({ event: "serviceCallResponse", callId: r.callId, response: plain(reader.readMessage(
    new Uint8Array(r.data.buffer, r.data.byteOffset, r.data.byteLength))) });
});
client.on("serviceCallFailure", (f) => out({ event: "serviceCallFailure", callId: f.callId,
  message: f.message }));
client.on("connectionGraphUpdate", (g) => out({ event: "connectionGraphUpdate",
  publishedTopics: g.publishedTopics, advertisedServices: g.advertisedServices }));
client.on("fetchAssetResponse", (r) => out({ event: "fetchAssetResponse",
  requestId: r.requestId, status: r.status, error: r.error,
  size: r.status === 0 ? r.data.byteLength : 0 }));

const commands = {
  subscribe({ topic }) {
    const channel = [...channels.values()].find((c) => c.topic === topic);
    const id = client.subscribe(channel.id);
    readers.set(id, { topic, reader: new MessageReader(definitions(channel.schema)) });
    return { subscriptionId: id };
  },
  subscribeId({ channelId }) { return { subscriptionId: client.subscribe(channelId) }; },
  unsubscribe({ subscriptionId }) { client.unsubscribe(subscriptionId); return {}; },
  advertise({ topic, schemaName, encoding = "cdr" }) {
    const id = client.advertise({ topic, encoding, schemaName });
    const channel = [...channels.values()].find((c) => c.schemaName === schemaName);
    if (channel) writers.set(id, new MessageWriter(definitions(channel.schema)));
    return { channelId: id };
  },
  publish({ channelId, message }) {
    client.sendMessage(channelId, writers.get(channelId).writeMessage(message));
    return {};
  },
  publishBytes({ channelId, hex }) {
    client.sendMessage(channelId, Buffer.from(hex, "hex"));
    return {};
  },
  call({ service, request, encoding = "cdr" }) {
    const s = services.get(service);
    const schema = s.request?.schema ?? s.requestSchema;
    const data = new MessageWriter(definitions(schema)).writeMessage(request);
    const callId = nextCallId++;
    client.sendServiceCallRequest({ serviceId: s.id, callId, encoding, data });
    return { callId };
  },
  callServiceId({ serviceId }) {
    const callId = nextCallId++;
    client.sendServiceCallRequest({ serviceId, callId, encoding: "cdr",
      data: new Uint8Array([0, 1, 0, 0]) });
    return { callId };
  },
  getParameters({ names, id }) { client.getParameters(names, id); return {}; },
  setParameters({ parameters, id }) { client.setParameters(parameters, id); return {}; },
  subscribeParameterUpdates({ names }) { client.subscribeParameterUpdates(names); return {}; },
  subscribeConnectionGraph() { client.subscribeConnectionGraph(); return {}; },
  fetchAsset({ uri, requestId }) { client.fetchAsset(uri, requestId); return {}; },
  rawText({ text }) { ws.send(text); return {}; },
  rawBinary({ hex, repeat = 1 }) {
    ws.send(Buffer.from(hex.repeat(repeat), "hex"));
    return {};
  },
  close() { client.close(); return {}; },
};

createInterface({ input: process.stdin }).on("line", (line) => {
  const command = JSON.parse(line);
  try {
    out({ event: "done", command: command.op, ...commands[command.op](command) });
  } catch (error) {
    out({ event: "failed", command: command.op, message: String(error?.stack ?? error) });
  }
}).on("close", () => { client.close(); setTimeout(() => process.exit(0), 200); });
