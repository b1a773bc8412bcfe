// Reads a `ydscope-cli check --report` file with parse5, the HTML5 parser jsdom uses, as a browser
// would: no parse errors at all, one criteria row per criterion of the run's JSON verdict with the
// same PASS/FAIL, and the pictures present as inline SVG with something drawn in them.
// usage: node check_report.mjs --report FILE.html --json VERDICT.json [--sector yes]
import { readFileSync } from "node:fs";
import { parse } from "parse5";

const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, word, i, all) => (i % 2 ? pairs : [...pairs, [word.replace(/^--/, ""), all[i + 1]]]), []),
);
const fail = (sentence) => {
  console.error(`check_report: ${sentence}`);
  process.exit(1);
};

const html = readFileSync(args.report, "utf8");
const verdict = JSON.parse(readFileSync(args.json, "utf8"));
const errors = [];
const document = parse(html, { onParseError: (e) => errors.push(`${e.code} at line ${e.startLine} col ${e.startCol}`) });
if (errors.length) fail(`the report has HTML parse errors: ${errors.slice(0, 5).join("; ")}`);

const all = [];
(function walk(node) {
  all.push(node);
  for (const child of node.childNodes ?? []) walk(child);
  if (node.content) walk(node.content);
})(document);
const attr = (node, name) => node.attrs?.find((a) => a.name === name)?.value;
const text = (node) => (node.nodeName === "#text" ? node.value : (node.childNodes ?? []).map(text).join(""));
const byTag = (tag, root = null) => (root ? all.filter((n) => n.tagName === tag && within(n, root)) : all.filter((n) => n.tagName === tag));
const within = (node, root) => {
  for (let n = node; n; n = n.parentNode) if (n === root) return true;
  return false;
};

const table = all.find((n) => n.tagName === "table" && attr(n, "id") === "criteria");
if (!table) fail("no table with id criteria");
const rows = byTag("tr", table).filter((r) => attr(r, "data-id"));
if (rows.length !== verdict.criteria.length)
  fail(`the table has ${rows.length} criteria rows, the JSON verdict ${verdict.criteria.length}`);
for (const criterion of verdict.criteria) {
  const row = rows.find((r) => attr(r, "data-id") === criterion.id);
  if (!row) fail(`criterion ${criterion.id} has no row`);
  const cells = byTag("td", row).map(text);
  if (cells.length !== 4) fail(`row ${criterion.id} has ${cells.length} cells, not 4`);
  if (cells[0] !== criterion.verdict.toUpperCase()) fail(`row ${criterion.id} says ${cells[0]}, the JSON ${criterion.verdict}`);
  if (cells[2] !== criterion.measured || cells[3] !== criterion.limit) fail(`row ${criterion.id} differs from the JSON`);
}
const badge = all.find((n) => attr(n, "id") === "verdict");
const expected = verdict.interrupted || verdict.failure ? "INCOMPLETE" : verdict.verdict.toUpperCase();
if (!badge || text(badge) !== expected) fail(`the verdict badge is not ${expected}`);

const svgs = byTag("svg");
const wanted = args.sector === "yes" ? 4 : 2;  // scan rate, polar; with a sector its histogram and valid share
if (svgs.length !== wanted) fail(`${svgs.length} SVG pictures, expected ${wanted}`);
for (const svg of svgs) {
  const title = byTag("title", svg).map(text)[0];
  if (!title) fail("an SVG picture has no title");
  if (!/^0 0 \d+ \d+$/.test(attr(svg, "viewbox") ?? attr(svg, "viewBox") ?? "")) fail(`"${title}" has no viewBox`);
  const marks = byTag("polyline", svg).length + byTag("rect", svg).length + byTag("path", svg).length;
  if (marks === 0) fail(`"${title}" draws nothing`);
}
const polar = svgs.find((s) => byTag("title", s).map(text)[0].includes("last lap"));
const points = (attr(byTag("path", polar).at(-1), "d") ?? "").split("M").length - 1;
if (points < 100) fail(`the polar snapshot holds ${points} points`);
const rate = svgs.find((s) => byTag("title", s).map(text)[0].includes("Scan rate"));
const laps = (attr(byTag("polyline", rate)[0] ?? {}, "points") ?? "").trim().split(/\s+/).length;
if (laps < verdict.timing.normal_laps) fail(`the scan-rate plot has ${laps} laps of ${verdict.timing.normal_laps}`);
console.log(`report ok: ${rows.length} criteria rows, ${svgs.length} pictures, ${points} points in the polar snapshot, ${laps} laps plotted`);
