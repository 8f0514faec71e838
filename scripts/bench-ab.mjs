// Two builds of the package against each other in one Node process, for a speed change on a
// noisy machine: runs in separate processes minutes apart can differ by 1.3-1.5x on a 2-core VM,
// far more than the few per cent a change is worth; runs of the two builds
// interleaved in one process share whatever the machine is doing at that moment.
//   node scripts/bench-ab.mjs DIR_A DIR_B [--method subpatch] [--size 512] [--runs 8]
// DIR_A and DIR_B each hold a built package (texsynth.js and texsynth_bg.wasm, as `pkg/` after
// ./scripts/build.sh). Methods: optimization, graphcut (entire patch), subpatch, flow (4 frames),
// features; the exemplar is www/samples/tiles_128.png. Each run is a new session from construction
// to done; the order alternates (A B, B A, ...). Prints each build's fastest and median time and
// the median and range of the per-pair ratio A / B (below 1: A is faster).
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { parseArgs } from 'node:util';
import { METHODS, makeSession } from './lib/bench-sessions.mjs';

const { values: opts, positionals } = parseArgs({
  allowPositionals: true,
  options: {
    method: { type: 'string', default: 'subpatch' },
    size: { type: 'string', default: '512' },
    runs: { type: 'string', default: '8' },
  },
});
if (positionals.length !== 2) {
  console.error('usage: node scripts/bench-ab.mjs DIR_A DIR_B [--method subpatch] [--size 512] [--runs 8]');
  process.exit(2);
}
const size = Number(opts.size);
const runs = Number(opts.runs);
if (!(size >= 8 && size <= 4096) || !(runs >= 1 && runs <= 1000)) {
  console.error(`--size must be 8 to 4096 and --runs 1 to 1000, got ${opts.size} and ${opts.runs}`);
  process.exit(2);
}

async function load(dir) {
  const lib = await import(pathToFileURL(resolve(dir, 'texsynth.js')).href);
  await lib.default({ module_or_path: readFileSync(resolve(dir, 'texsynth_bg.wasm')) });
  return lib;
}

const png = readFileSync(new URL('../www/samples/tiles_128.png', import.meta.url));
function timeOne(lib) {
  const exemplar = lib.Exemplar.fromBytes(png);
  const start = performance.now();
  const session = makeSession(lib, opts.method, exemplar, size, 4);
  while (!session.done) session.step();
  const ms = performance.now() - start;
  session.free();
  exemplar.free();
  return ms;
}

if (!METHODS.includes(opts.method)) {
  console.error(`unknown --method ${opts.method}: one of ${METHODS.join(', ')}`);
  process.exit(2);
}
const builds = { A: await load(positionals[0]), B: await load(positionals[1]) };
const times = { A: [], B: [] };
for (let i = 0; i < runs; i++) {
  for (const k of i % 2 ? ['B', 'A'] : ['A', 'B']) times[k].push(timeOne(builds[k]));
}
const sorted = (v) => [...v].sort((a, b) => a - b);
const median = (v) => sorted(v)[v.length >> 1];
for (const k of ['A', 'B']) {
  const v = times[k];
  console.log(`${k} (${positionals[k === 'A' ? 0 : 1]}): fastest ${Math.min(...v).toFixed(0)} ms, median ${median(v).toFixed(0)} ms, all ${v.map((x) => x.toFixed(0)).join(' ')}`);
}
const ratios = sorted(times.A.map((a, i) => a / times.B[i]));
console.log(`A / B per pair (${opts.method}, ${size}x${size}, ${runs} pairs): median ${median(ratios).toFixed(3)}, range ${ratios[0].toFixed(3)} to ${ratios[ratios.length - 1].toFixed(3)}`);
