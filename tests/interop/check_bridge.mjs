// ydscope-cli serve, checked with Foxglove's own WebSocket client (@foxglove/ws-protocol) and
// ROS 2 deserialiser. Usage: node check_bridge.mjs ws://HOST:PORT
// Connects, expects serverInfo and the advertised topics, subscribes to /scan and decodes 20
// laps (REP-117's values, no intensities, stamped at the first ray), sets scan_hz through parameters and sees the read-back and the lap rate follow, and checks
// that malformed and oversized client messages get a status message while the stream goes on.
import wsProtocol from "@foxglove/ws-protocol";
import WebSocket from "ws";
import { parse as parseMessageDefinition } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";

const { FoxgloveClient } = wsProtocol;
const url = process.argv[2];
const fail = (what) => {
  console.error(`FAIL: ${what}`);
  process.exit(1);
};
const ok = (what) => console.log(`ok: ${what}`);
setTimeout(() => fail("timed out after 60 s"), 60000).unref();

const ws = new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
const client = new FoxgloveClient({ ws });
const statuses = [];
const waiters = [];
const scans = [];
let serverInfo;
let channels;
let reader;
client.on("serverInfo", (info) => (serverInfo = info));
client.on("status", (s) => statuses.push(s));
client.on("error", (e) => fail(`client error: ${e}`));
client.on("advertise", (advertised) => (channels = advertised));
client.on("message", ({ timestamp, data }) => {
  const scan = reader.readMessage(data);
  scans.push({ at: Number(timestamp) / 1e9, timestamp: BigInt(timestamp), scan });
});
const parameterReplies = [];
client.on("parameterValues", (p) => parameterReplies.push(p));
const until = async (what, test, ms = 15000) => {
  const start = Date.now();
  while (!test()) {
    if (Date.now() - start > ms) fail(`waited ${ms} ms for ${what}`);
    await new Promise((r) => setTimeout(r, 20));
  }
};

await until("serverInfo and advertise", () => serverInfo && channels);
if (!serverInfo.capabilities.includes("parameters")) fail("serverInfo lacks the parameters capability");
const topics = channels.map((c) => c.topic).sort();
for (const t of ["/diagnostics", "/points", "/scan", "/ydscope/device_bytes", "/ydscope/host_bytes"]) if (!topics.includes(t)) fail(`${t} is not advertised`);
for (const c of channels) if (c.encoding !== "cdr" || c.schemaEncoding !== "ros2msg") fail(`${c.topic} is not cdr/ros2msg`);
ok(`serverInfo "${serverInfo.name}", ${channels.length} topics advertised as cdr with ros2msg schemas`);

const scanChannel = channels.find((c) => c.topic === "/scan");
reader = new MessageReader(parseMessageDefinition(scanChannel.schema, { ros2: true }));
client.subscribe(scanChannel.id);
await until("20 laps on /scan", () => scans.length >= 20);
for (const { timestamp, scan } of scans) {
  if (scan.ranges.length < 2 || Math.abs(scan.angle_min + Math.PI) > 1e-6) fail("a /scan message is not a full turn");
  // +Inf is REP-117's "no return", NaN an empty bin: neither is a return.
  const returns = scan.ranges.filter((r) => Number.isFinite(r) && r > 0).length;
  if (returns < scan.ranges.length / 4) fail("a /scan message has almost no returns");
  if (scan.ranges.some((r) => r === 0)) fail("a /scan range is 0, which reads as a return at the sensor");
  if (scan.intensities.length !== 0) fail(`a /scan message of the G6 has ${scan.intensities.length} intensities; it measures no return strength`);
  if (!(scan.range_min > 0 && scan.range_max === 25)) fail(`/scan range ${scan.range_min}..${scan.range_max} m is not the G6's`);
  // Stamped at the first ray, sent when the closing byte came: one lap's scan_time apart.
  const stamp = BigInt(scan.header.stamp.sec) * 1000000000n + BigInt(scan.header.stamp.nanosec);
  if (!(scan.scan_time > 0)) fail(`a /scan message's scan_time is ${scan.scan_time}`);
  const sinceStamp = Number(timestamp - stamp) / 1e9;
  if (Math.abs(sinceStamp - scan.scan_time) > 1e-6) fail(`a /scan stamp is ${sinceStamp} s before its message, scan_time ${scan.scan_time} s`);
  if (Math.abs(scan.time_increment * scan.ranges.length - scan.scan_time) > 1e-6) fail(`time_increment ${scan.time_increment} does not divide scan_time ${scan.scan_time} among the samples`);
}
ok(`/scan: ${scans.length} laps decoded, ${scans[0].scan.ranges.length} bins each, no intensities, ` +
  `stamped at the first ray (${scans[0].scan.scan_time.toFixed(4)} s before the closing byte)`);

// Malformed, unknown and oversized messages: a status each, and the stream goes on.
const before = statuses.length;
ws.send("{not json");
ws.send(JSON.stringify({ op: "fly" }));
ws.send(JSON.stringify({ op: "subscribe", subscriptions: [{ id: 99, channelId: 12345 }] }));
ws.send("x".repeat(200 * 1024));
await until("four status messages", () => statuses.length >= before + 4);
const seen = scans.length;
await until("laps after the bad messages", () => scans.length >= seen + 5);
if (!statuses.slice(before).some((s) => s.message.includes(`${200 * 1024} bytes`))) fail("the oversized message's status does not give its size");
ok(`bad client messages each got a status (${statuses.slice(before, before + 4).map((s) => JSON.stringify(s.message.slice(0, 40))).join(", ")}) and /scan went on`);

// Parameters: scan_hz through the session's command path; the read-back is what we see.
client.getParameters(["scan_hz"], "get-1");
await until("getParameters reply", () => parameterReplies.some((p) => p.id === "get-1"));
const initial = parameterReplies.find((p) => p.id === "get-1").parameters.find((p) => p.name === "scan_hz");
if (!initial) fail("getParameters has no scan_hz");
const target = initial.value > 8 ? 6 : 10;
client.setParameters([{ name: "scan_hz", value: target }], "set-1");
await until("setParameters read-back", () => parameterReplies.some((p) => p.id === "set-1"), 30000);
const readBack = parameterReplies.find((p) => p.id === "set-1").parameters.find((p) => p.name === "scan_hz");
if (!readBack || Math.abs(readBack.value - target) > 0.25) fail(`scan_hz read back ${readBack?.value}, asked ${target}`);
const mark = scans.length;
await until("laps at the new rate", () => scans.length >= mark + 25, 30000);
const recent = scans.slice(-20);
const rate = (recent.length - 1) / (recent.at(-1).at - recent[0].at);
if (Math.abs(rate - target) > target * 0.1) fail(`laps arrive at ${rate.toFixed(2)} Hz after setting ${target} Hz`);
ok(`scan_hz ${initial.value} -> ${target}: read back ${readBack.value}, laps now at ${rate.toFixed(2)} Hz`);
client.close();
process.exit(0);
