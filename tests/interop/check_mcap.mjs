// Independent check of an MCAP file written by ydscope, with readers nobody here wrote: the
// official @mcap/core readers (indexed and streaming, CRCs validated) and Foxglove's ROS 2
// deserialiser. Usage:
//   node check_mcap.mjs --cli YDSCOPE_CLI --mcap FILE --source REC.ydrec|RAW [--model MODEL] [--killed yes]
//                       [--sources NAME,NAME...]
// It checks that every message decodes, that the summary agrees with the messages, that /points
// equals the returns of what `ydscope-cli decode SOURCE` prints (G1's flag as interference_flag),
// that /scan is decode's laps binned as the official ROS 2 driver bins with REP-117's values
// (+Inf no return, NaN an empty bin, no intensities) and stamped at each lap's first ray, and
// that the raw channel decodes again to the same laps.
// --killed yes: FILE is what a killed recorder left (no summary): a streaming reader must recover
// its flushed chunks, and their laps must be the first laps of SOURCE (also cut off by the kill).
// --sources: FILE holds several lidars; each one's /NAME/points, /NAME/scan and /NAME/diagnostics
// are checked against decode's laps of that source, and /tf_static must place every NAME and be
// offered transient-local. Every file's messages must be in log-time order in file order.
// Prints one line per check; exits 1 on the first failure with what differed.
import { execFileSync } from "node:child_process";
import { mkdtempSync, openSync, readFileSync, readSync, fstatSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { McapIndexedReader, McapStreamReader } from "@mcap/core";
import { loadDecompressHandlers } from "@mcap/support";
import { parse as parseMessageDefinition } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";

const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, arg, i, all) => (arg.startsWith("--") ? [...pairs, [arg.slice(2), all[i + 1]]] : pairs), []),
);
for (const required of ["cli", "mcap", "source"]) {
  if (!args[required]) {
    console.error(`check_mcap: missing --${required}`);
    process.exit(2);
  }
}

function fail(what) {
  console.error(`FAIL: ${what}`);
  process.exit(1);
}
function ok(what) {
  console.log(`ok: ${what}`);
}

process.on("uncaughtException", (error) => fail(error?.message ?? String(error)));
const decompressHandlers = await loadDecompressHandlers();
const fd = openSync(args.mcap, "r");
const readable = {
  size: async () => BigInt(fstatSync(fd).size),
  read: async (offset, size) => {
    const buffer = new Uint8Array(Number(size));
    readSync(fd, buffer, 0, Number(size), Number(offset));
    return buffer;
  },
};

const killed = args.killed === "yes";
const readers = new Map();
const byTopic = new Map();
const qosByTopic = new Map();
const addChannel = (id, channel, schema) => {
  if (channel.messageEncoding !== "cdr") fail(`${channel.topic} is ${channel.messageEncoding}, not cdr`);
  if (!schema || schema.encoding !== "ros2msg") fail(`${channel.topic} has no ros2msg schema`);
  if (!channel.metadata.get("offered_qos_profiles")) fail(`${channel.topic} lacks offered_qos_profiles (ros2 profile)`);
  qosByTopic.set(channel.topic, channel.metadata.get("offered_qos_profiles"));
  const text = new TextDecoder().decode(schema.data);
  readers.set(id, { topic: channel.topic, type: schema.name, reader: new MessageReader(parseMessageDefinition(text, { ros2: true })) });
};
const addMessage = (message) => {
  const channel = readers.get(message.channelId);
  if (!channel) fail(`message on unknown channel ${message.channelId}`);
  let decoded;
  try {
    decoded = channel.reader.readMessage(message.data);
  } catch (error) {
    fail(`message ${message.sequence} on ${channel.topic} does not decode as ${channel.type}: ${error}`);
  }
  if (!byTopic.has(channel.topic)) byTopic.set(channel.topic, []);
  byTopic.get(channel.topic).push({ logTime: message.logTime, decoded });
};

if (!killed) {
// 1. Indexed reader: the summary, the chunk indexes, every message through the index.
const indexed = await McapIndexedReader.Initialize({ readable, decompressHandlers });
if (indexed.header.profile !== "ros2") fail(`profile is '${indexed.header.profile}', not ros2`);
for (const [id, channel] of indexed.channelsById) addChannel(id, channel, indexed.schemasById.get(channel.schemaId));
const stats = indexed.statistics;
if (!stats) fail("no Statistics record in the summary");
const counts = new Map();
let first = undefined, last = undefined, total = 0n;
for await (const message of indexed.readMessages()) {
  addMessage(message);
  counts.set(message.channelId, (counts.get(message.channelId) ?? 0n) + 1n);
  first = first === undefined || message.logTime < first ? message.logTime : first;
  last = last === undefined || message.logTime > last ? message.logTime : last;
  total += 1n;
}
if (stats.messageCount !== total) fail(`statistics say ${stats.messageCount} messages, the index gives ${total}`);
if (stats.chunkCount !== indexed.chunkIndexes.length) fail(`statistics say ${stats.chunkCount} chunks, ${indexed.chunkIndexes.length} chunk indexes`);
if (stats.channelCount !== indexed.channelsById.size) fail("statistics channel count disagrees");
if (total > 0n && (stats.messageStartTime !== first || stats.messageEndTime !== last)) fail("statistics start/end times disagree with the messages");
for (const [id, n] of counts) if (stats.channelMessageCounts.get(id) !== n) fail(`channel ${id}: statistics ${stats.channelMessageCounts.get(id)} vs ${n} messages`);
ok(`indexed reader: ${total} messages on ${readers.size} channels in ${indexed.chunkIndexes.length} chunks, every one decodes; statistics agree`);

// 2. Streaming reader over the whole file, CRCs validated: the same messages.
const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
stream.append(readFileSync(args.mcap));
let streamed = 0n, footer = false, latest = 0n;
for (let record; (record = stream.nextRecord()); ) {
  if (record.type === "Message") {
    streamed += 1n;
    // In file order, as a reader streaming the file meets them: never back in log time.
    if (record.logTime < latest) fail(`message ${streamed} (log time ${record.logTime}) is written after one at ${latest}`);
    latest = record.logTime;
  }
  if (record.type === "Footer") footer = true;
}
if (!stream.done() || !footer) fail("streaming reader did not reach the footer");
if (streamed !== total) fail(`streaming reader found ${streamed} messages, the index ${total}`);
ok(`streaming reader: ${streamed} messages in log-time order, data/chunk/summary CRCs valid`);

} else {
  // What a killed recorder left: read it as a stream, as far as it goes.
  const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
  stream.append(readFileSync(args.mcap));
  const schemas = new Map();
  let recovered = 0;
  for (let record; (record = stream.nextRecord()); ) {
    if (record.type === "Schema") schemas.set(record.id, record);
    if (record.type === "Channel") addChannel(record.id, record, schemas.get(record.schemaId));
    if (record.type === "Message") {
      addMessage(record);
      recovered += 1;
    }
  }
  if (recovered === 0) fail("the killed recorder's MCAP gives no message to a streaming reader");
  ok(`streaming reader recovers ${recovered} messages from the killed recorder's MCAP, every one decodes`);
}

// 3. /points equals `ydscope-cli decode SOURCE`.
const decodeArgs = (source) => ["decode", ...(args.model ? ["--model", args.model] : []), source];
const laps = (jsonl) => jsonl.split("\n").filter((l) => l.startsWith('{"type":"lap"')).map((l) => JSON.parse(l));
const decodedText = execFileSync(args.cli, decodeArgs(args.source), { maxBuffer: 1 << 30 }).toString();
const names = args.sources ? args.sources.split(",") : [undefined];
for (const name of names) checkLidar(name);

// One lidar's topics (under /NAME with several) against decode's laps of it.
function checkLidar(name) {
const prefix = name === undefined ? "" : `/${name}`;
const expected = laps(decodedText).filter((lap) => lap.source === name);
if (name !== undefined && expected.length === 0) fail(`decode printed no lap of source ${name}`);
const clouds = byTopic.get(`${prefix}/points`) ?? [];
const scans = byTopic.get(`${prefix}/scan`) ?? [];
if (killed) {
  // Both files were cut by the kill at different moments: compare the laps both have.
  if (clouds.length === 0) fail("no /points message recovered");
  if (clouds.length > expected.length + 2) fail(`/points has ${clouds.length} laps, the recording only ${expected.length}`);
  expected.length = Math.min(expected.length, clouds.length, scans.length);
  clouds.length = scans.length = expected.length;
}
if (clouds.length !== expected.length) fail(`${prefix}/points has ${clouds.length} messages, decode printed ${expected.length} laps`);
if (scans.length !== expected.length) fail(`${prefix}/scan has ${scans.length} messages, decode printed ${expected.length} laps`);
// The lidar's model, as its /diagnostics name it: only a G1 flags interference.
const diagnostics = byTopic.get(`${prefix}/diagnostics`) ?? [];
if (diagnostics.length === 0) fail(`no ${prefix}/diagnostics messages`);
const values = Object.fromEntries(diagnostics.at(-1).decoded.status[0].values.map((kv) => [kv.key, kv.value]));
const flagged = (args.model ?? values.model) === "G1";
const cloudPoints = (cloud) => {
  const view = new DataView(cloud.data.buffer, cloud.data.byteOffset, cloud.data.byteLength);
  const field = Object.fromEntries(cloud.fields.map((f) => [f.name, f.offset]));
  const names = cloud.fields.map((f) => f.name).join(",");
  const want = `x,y,z,range,angle${flagged ? ",interference_flag" : ""}`;
  if (names !== want) fail(`/points fields are ${names}, expected ${want}`);
  if (!cloud.is_dense) fail("/points is not dense");
  const points = [];
  for (let i = 0; i < cloud.width; i++) {
    const at = i * cloud.point_step;
    points.push({
      x: view.getFloat32(at + field.x, true), y: view.getFloat32(at + field.y, true),
      range: view.getFloat32(at + field.range, true), angle: view.getFloat32(at + field.angle, true),
      flag: flagged ? view.getUint8(at + field.interference_flag) : 0,
    });
  }
  return points;
};
let pointCount = 0, noReturns = 0;
for (let i = 0; i < expected.length; i++) {
  const points = cloudPoints(clouds[i].decoded);
  // A sample without a return is no point: /points holds decode's returns, in order.
  const want = expected[i].points.filter(([, rangeMm]) => rangeMm !== 0);
  noReturns += expected[i].points.length - want.length;
  if (points.length !== want.length) fail(`lap ${i}: /points has ${points.length} points, decode ${want.length} returns`);
  for (let j = 0; j < want.length; j++) {
    const [angle, rangeMm, flag] = want[j];
    const p = points[j];
    // decode prints angles with 4 decimals and ranges (mm) with 2: equal within that rounding.
    if (Math.abs(p.angle - angle) > 0.00005 + 1e-6 * Math.abs(angle)) fail(`lap ${i} point ${j}: angle ${p.angle} vs decode ${angle}`);
    if (Math.abs(p.range * 1000 - rangeMm) > 0.005 + 1e-6 * rangeMm) fail(`lap ${i} point ${j}: range ${p.range} m vs decode ${rangeMm} mm`);
    if (p.flag !== flag) fail(`lap ${i} point ${j}: flag ${p.flag} vs decode ${flag}`);
    if (!(p.range > 0)) fail(`lap ${i} point ${j}: a point at the origin in a dense cloud`);
  }
  pointCount += want.length;
}
ok(`${prefix}/points: ${expected.length} laps, ${pointCount} points equal to the returns of ydscope-cli decode ` +
  `(${noReturns} samples without a return left out), dense, ${flagged ? "with" : "without"} interference_flag`);

// 4. /scan is decode's laps binned as the official driver bins (YDLidar-SDK + ydlidar_ros2_driver):
// ROS angle = normalize(2pi - (deg + pi)), increment 2pi/(n-1), bin ceil((angle + pi)/increment),
// later points overwrite; where the driver writes 0, REP-117's values: +Inf no return or beyond
// range_max, -Inf below range_min, NaN a bin no sample fell in. Returns are binned by /points'
// exact angles; a sample without a return has only decode's 4 decimals, so a bin it may fall in
// either side of is not compared (counted below).
const rosAngle = (deg) => {
  let a = (deg * Math.PI) / 180 + Math.PI;
  a = 2 * Math.PI - a;
  a = ((a % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
  return a > Math.PI ? a - 2 * Math.PI : a;
};
const stampNs = (header) => BigInt(header.stamp.sec) * 1000000000n + BigInt(header.stamp.nanosec);
let unsure = 0, infinite = 0, empty = 0;
for (let i = 0; i < expected.length; i++) {
  const scan = scans[i].decoded;
  const returns = cloudPoints(clouds[i].decoded);
  const samples = expected[i].points;
  const bins = Math.max(samples.length, 2);
  const increment = (2 * Math.PI) / (bins - 1);
  const binOf = (deg) => Math.ceil((rosAngle(deg) + Math.PI) / increment);
  const ranges = new Array(bins).fill(NaN);
  const skip = new Set();
  let next = 0;
  for (const [angle, rangeMm] of samples) {
    if (rangeMm === 0) {
      const [low, high] = [binOf(angle - 0.00006), binOf(angle + 0.00006)];
      if (low !== high) [low, high].forEach((b) => skip.add(b));
      const index = binOf(angle);
      if (index >= 0 && index < bins) ranges[index] = Infinity;
      continue;
    }
    const p = returns[next++];
    const index = binOf(p.angle);
    if (index >= 0 && index < bins)
      ranges[index] = p.range > scan.range_max ? Infinity : p.range < scan.range_min ? -Infinity : p.range;
  }
  if (Math.abs(scan.angle_min + Math.PI) > 1e-6 || Math.abs(scan.angle_max - Math.PI) > 1e-6) fail(`lap ${i}: /scan angle range is not -pi..pi`);
  if (Math.fround(increment) !== scan.angle_increment) fail(`lap ${i}: angle_increment ${scan.angle_increment}, expected ${increment}`);
  if (scan.ranges.length !== bins) fail(`lap ${i}: ${scan.ranges.length} bins, expected ${bins}`);
  for (let b = 0; b < bins; b++) {
    if (skip.has(b)) continue;
    if (!Object.is(scan.ranges[b], Math.fround(ranges[b]))) fail(`lap ${i} bin ${b}: /scan ${scan.ranges[b]}, binned decode ${ranges[b]}`);
    if (scan.ranges[b] === Infinity) infinite++;
    if (Number.isNaN(scan.ranges[b])) empty++;
  }
  unsure += skip.size;
  if (scan.ranges.some((r) => r === 0)) fail(`lap ${i}: a /scan range is 0, which reads as a return at the sensor`);
  if (scan.intensities.length !== 0) fail(`lap ${i}: /scan has ${scan.intensities.length} intensities; no unit here measures return strength`);
  // Stamped at the first ray: the lap's first receive time, one lap before its closing byte (the
  // log time), and the previous lap's closing byte is the first byte of this lap's zero packet.
  const stamp = stampNs(scan.header);
  if (stamp !== stampNs(clouds[i].decoded.header) || scans[i].logTime !== clouds[i].logTime) fail(`lap ${i}: /scan and /points stamps differ`);
  if (!(scan.scan_time > 0)) fail(`lap ${i}: scan_time ${scan.scan_time}, not the lap's duration`);
  const sinceStamp = Number(scans[i].logTime - stamp) / 1e9;
  if (Math.abs(sinceStamp - scan.scan_time) > 1e-6) fail(`lap ${i}: stamp is ${sinceStamp} s before the closing byte, scan_time says ${scan.scan_time}`);
  if (Math.abs(scan.time_increment * samples.length - scan.scan_time) > 1e-6) fail(`lap ${i}: time_increment ${scan.time_increment} x ${samples.length} samples is not scan_time ${scan.scan_time}`);
  if (i > 0 && !killed) {
    const closeToDecode = Number(scans[i].logTime - scans[0].logTime) / 1e9 - (expected[i].t - expected[0].t);
    if (Math.abs(closeToDecode) > 2e-6) fail(`lap ${i}: logged ${closeToDecode} s off decode's closing time`);
    const gap = Number(stamp - scans[i - 1].logTime) / 1e9;
    if (expected[i].index === expected[i - 1].index + 1 && (gap > 0 || gap < -0.1 * scan.scan_time))
      fail(`lap ${i}: stamped ${gap} s from the previous lap's closing byte, not at the first byte of the zero packet that closed it`);
  }
}
ok(`${prefix}/scan: ${scans.length} scans binned as the official driver would, with ${infinite} +Inf (no return) and ` +
  `${empty} NaN (empty) bins, ${unsure} bins too close to call; no intensities; stamped at each lap's first ray`);

// 5. /diagnostics: decodes, names the device and its counters.
for (const key of ["model", "health", "scan_hz_set", "scan_hz_measured", "ranging_khz", "checksum_errors", "laps"])
  if (!(key in values)) fail(`/diagnostics lacks ${key}`);
if (!killed && Number(values.laps) !== expected.length) fail(`/diagnostics says ${values.laps} laps, decode ${expected.length}`);
ok(`${prefix}/diagnostics: ${diagnostics.length} messages, last says model ${values.model}, ${values.laps} laps, measured ${values.scan_hz_measured} Hz`);

// 6. The raw channel decodes again exactly like the source.
const raw = byTopic.get(`${prefix}/ydscope/device_bytes`);
if (raw && !killed && name === undefined) {
  const bytes = Buffer.concat(raw.map((m) => Buffer.from(m.decoded.data)));
  const dir = mkdtempSync(join(tmpdir(), "ydscope-mcap-"));
  writeFileSync(join(dir, "device.bin"), bytes);
  const model = args.model ?? values.model;
  // Read with the conventions /diagnostics names (an old recording was read as the manuals say).
  if (!values.conventions) fail("/diagnostics names no conventions");
  const reading = values.conventions.endsWith("manual") ? "manual" : "field";
  const again = execFileSync(args.cli, ["decode", "--model", model, "--conventions", reading, join(dir, "device.bin")], {
    maxBuffer: 1 << 30,
  }).toString();
  // The laps, without their times: bytes written out alone carry no receive times, so decode
  // times them at the baud rate (`t`), where the source had recorded ones.
  const lapsOnly = (text) =>
    text.split("\n").filter((l) => l.startsWith('{"type":"lap"')).map((l) => l.replace(/,"t":[0-9.]+,/, ",")).join("\n");
  if (lapsOnly(again) !== lapsOnly(decodedText)) fail("the bytes of /ydscope/device_bytes decode to other laps than the source");
  ok(`/ydscope/device_bytes: ${bytes.length} bytes decode again to the same ${expected.length} laps`);
}
}

// 7. /tf_static places each lidar (one too: its /scan's frame) in the robot's frame, with its unit frame.
{
  const tf = byTopic.get("/tf_static") ?? [];
  if (tf.length === 0) fail("no /tf_static message");
  const frames = args.sources ? names : [byTopic.get("/scan")[0].decoded.header.frame_id];
  const transforms = tf[0].decoded.transforms;
  const children = transforms.map((t) => t.child_frame_id);
  for (const name of frames) {
    if (!children.includes(name)) fail(`/tf_static has no transform to ${name} (it has ${children})`);
    // Each lidar's unit frame (its 0 degrees and sweep) hangs from its laser frame.
    const unit = transforms.find((t) => t.child_frame_id === `${name}_unit`);
    if (!unit || unit.header.frame_id !== name) fail(`/tf_static has no ${name}_unit under ${name}`);
  }
  const mounts = transforms.filter((t) => frames.includes(t.child_frame_id));
  const parents = new Set(mounts.map((t) => t.header.frame_id));
  if (parents.size !== 1) fail(`/tf_static places the lidars in ${[...parents]}, not one robot frame`);
  ok(`/tf_static: ${mounts.length} lidar(s) placed in ${[...parents][0]} (${frames.join(", ")}), each with its unit frame`);
  // Latched, as rosbag2 records a transient-local topic, so tf2's static listener gets it on replay.
  const qos = qosByTopic.get("/tf_static");
  for (const line of ["- history: 1", "  depth: 1", "  reliability: 1", "  durability: 1"])
    if (!qos.split("\n").includes(line)) fail(`/tf_static's offered_qos_profiles lacks '${line}':\n${qos}`);
  ok("/tf_static offered reliable, transient-local, keep-last 1");
}
