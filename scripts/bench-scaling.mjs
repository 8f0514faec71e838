// How time and memory grow: every method as wasm in Node, one fresh process
// per case (wasm memory never shrinks, so a run's peak is the memory's size after it).
//   node scripts/bench-scaling.mjs [--outputs 256,512,1024,2048,4096] [--exemplars 64,128,256,512,1024,3000]
//                                  [--methods optimization,graphcut,subpatch,features,flow]
//                                  [--svg www/scaling.svg] [--repeat 1]
// Output sweep: the 128x128 www/samples/tiles_128.png to each square output size, up to each
// method's LARGEST (4096 for every method: flow animation's 4096x4096 case takes
// about 3 minutes, the whole run about 9). Exemplar sweep: gravel (the 512x512
// ../shared/textures/gravel_full.png, shrunk with Exemplar.resized below 512 and mirror-tiled
// above it) to a 256x256 output. Flow animation is timed per frame after the first (frames per
// second over 4 frames); every other method runs to done. Prints two markdown tables (total
// time, longest step, peak wasm memory) and writes a log-log plot of time against output pixels
// as SVG. `--repeat N` runs every case N times, each in a fresh process, and reports the best
// run with the range of all (this machine's speed swings by up to 1.5x within an hour: the best
// of several is what the code costs, the range what a user may see). `--case method:size:side`
// runs one case once and prints it as JSON. Needs the wasm package: ./scripts/build.sh.
import { spawnSync } from 'node:child_process';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import { fileURLToPath } from 'node:url';
import { makeSession } from './lib/bench-sessions.mjs';

const MiB = 1 << 20;
const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, arg, i, all) => (arg.startsWith('--') ? [...pairs, [arg.slice(2), all[i + 1]]] : pairs), []),
);
const METHODS = {
  optimization: 'texture optimisation',
  graphcut: 'graph cut, entire patch',
  subpatch: 'graph cut, sub-patch',
  features: 'feature-guided',
  flow: 'flow animation (per frame)',
};
const FLOW_FRAMES = 4;
/** The largest output each method runs at (lower a method's to skip its slowest cases). */
const LARGEST = { optimization: 4096, graphcut: 4096, subpatch: 4096, features: 4096, flow: 4096 };

/** Builds the exemplar of a case: tiles_128, or gravel at `side` pixels. */
function exemplarOf(lib, side) {
  const read = (path) => readFileSync(new URL(path, import.meta.url));
  if (!side) return lib.Exemplar.fromBytes(read('../www/samples/tiles_128.png'));
  const full = lib.Exemplar.fromBytes(read('../../shared/textures/gravel_full.png'));
  if (side <= full.width) return side === full.width ? full : full.resized(side);
  // Mirror-tiled: a photo-sized exemplar with the texture's statistics and no seams.
  const rgba = new Uint8ClampedArray(full.width * full.height * 4);
  full.renderInto(rgba);
  const out = new Uint8ClampedArray(side * side * 4);
  const fold = (v, n) => {
    const m = v % (2 * n);
    return m < n ? m : 2 * n - 1 - m;
  };
  for (let y = 0; y < side; y++) {
    const sy = fold(y, full.height);
    for (let x = 0; x < side; x++) {
      const s = (sy * full.width + fold(x, full.width)) * 4;
      out.set(rgba.subarray(s, s + 4), (y * side + x) * 4);
    }
  }
  return lib.Exemplar.fromRgba(out, side, side);
}

async function runCase(method, size, exemplarSide) {
  const lib = await import('../pkg/texsynth.js');
  const wasm = await lib.default({ module_or_path: readFileSync(new URL('../pkg/texsynth_bg.wasm', import.meta.url)) });
  const exemplar = exemplarOf(lib, exemplarSide);
  const start = performance.now();
  const session = makeSession(lib, method, exemplar, size, FLOW_FRAMES);
  let longest = 0;
  let steps = 0;
  let firstFrame = 0;
  while (!session.done) {
    const t = performance.now();
    const event = session.step();
    const dt = performance.now() - t;
    longest = Math.max(longest, dt);
    steps++;
    if (method === 'flow' && !firstFrame && event.kind === 'frame') firstFrame = performance.now();
  }
  const end = performance.now();
  const fps = method === 'flow' && firstFrame ? ((FLOW_FRAMES - 1) * 1000) / (end - firstFrame) : null;
  return { ms: end - start, longest, steps, fps, peak: wasm.memory.buffer.byteLength };
}

if (args.case) {
  const [method, size, side] = args.case.split(':');
  console.log(JSON.stringify(await runCase(method, Number(size), Number(side))));
  process.exit(0);
}

// `--exemplars none` (or any list without a size) skips the exemplar sweep; likewise outputs.
const sizes = (list) => list.split(',').map(Number).filter((n) => n > 0);
const outputs = sizes(args.outputs ?? '256,512,1024,2048,4096');
const exemplars = sizes(args.exemplars ?? '64,128,256,512,1024,3000');
const methods = (args.methods ?? Object.keys(METHODS).join(',')).split(',');
const script = fileURLToPath(import.meta.url);

const repeat = Math.max(1, Math.round(Number(args.repeat ?? 1)) || 1);

function measureOnce(method, size, side) {
  const child = spawnSync(process.execPath, [script, '--case', `${method}:${size}:${side}`], { encoding: 'utf8', maxBuffer: 1 << 20 });
  if (child.status !== 0) {
    const msg = (child.stderr.match(/Error: (.*)/) ?? [, child.stderr.trim().split('\n').pop()])[1];
    return { error: msg };
  }
  return JSON.parse(child.stdout.trim().split('\n').pop());
}

/** The best of `repeat` runs (the shortest time, or the most frames per second), with `runs`
 * holding every run's time or rate; the first failure is returned as it is. */
function measure(method, size, side) {
  const runs = [];
  for (let i = 0; i < repeat; i++) {
    const r = measureOnce(method, size, side);
    if (r.error) return r;
    runs.push(r);
  }
  const score = (r) => (r.fps != null ? -r.fps : r.ms);
  const best = runs.reduce((a, b) => (score(b) < score(a) ? b : a));
  return { ...best, runs: runs.map((r) => r.fps ?? r.ms) };
}

const cell = (r) => {
  if (!r) return '| not run | | |';
  if (r.error) return `| failed: ${r.error} | | |`;
  const fps = r.fps != null;
  const figure = (v) => (fps ? v : v / 1000).toFixed(2);
  const range = r.runs?.length > 1 ? ` (${r.runs.length} runs: ${figure(Math.min(...r.runs))}-${figure(Math.max(...r.runs))})` : '';
  return `| ${figure(fps ? r.fps : r.ms)} ${fps ? 'fps' : 's'}${range} | ${r.longest.toFixed(0)} ms | ${(r.peak / MiB).toFixed(0)} MiB |`;
};

const results = {};
console.log(`wasm (Node ${process.version}), one process per case${repeat > 1 ? ` run ${repeat} times (the best, and the range of all runs)` : ''}; time to done (flow: frames per second after the first), longest step, peak wasm memory`);
console.log('\nOutput size (tiles_128.png):\n');
console.log('| method | output | pixels | time | longest step | peak memory |');
console.log('|---|---|---:|---:|---:|---:|');
for (const method of methods) {
  results[method] = [];
  for (const size of outputs) {
    const r = size > LARGEST[method] ? null : measure(method, size, 0);
    if (r && !r.error) results[method].push({ pixels: size * size, ms: r.fps != null ? 1000 / r.fps : r.ms });
    console.log(`| ${METHODS[method]} | ${size}x${size} | ${size * size} ${cell(r)}`);
  }
}
if (exemplars.length) {
  console.log('\nExemplar size (gravel, shrunk or mirror-tiled) to 256x256:\n');
  console.log('| method | exemplar | time | longest step | peak memory |');
  console.log('|---|---|---:|---:|---:|');
}
for (const method of methods.filter((m) => m !== 'flow')) {
  for (const side of exemplars) {
    console.log(`| ${METHODS[method]} | ${side}x${side} ${cell(measure(method, 256, side))}`);
  }
}

// A log-log plot of time (per frame for flow) against output pixels.
const svgPath = args.svg ?? 'www/scaling.svg';
const [W, H, L, B] = [560, 340, 60, 40];
const all = Object.values(results).flat();
if (all.length) {
  const lx = (p) => Math.log10(p);
  const ly = (ms) => Math.log10(ms);
  const [x0, x1] = [lx(Math.min(...all.map((r) => r.pixels))), lx(Math.max(...all.map((r) => r.pixels)))];
  const [y0, y1] = [Math.floor(ly(Math.min(...all.map((r) => r.ms)))), Math.ceil(ly(Math.max(...all.map((r) => r.ms))))];
  const px = (p) => L + ((lx(p) - x0) / (x1 - x0 || 1)) * (W - L - 150);
  const py = (ms) => H - B - ((ly(ms) - y0) / (y1 - y0 || 1)) * (H - B - 20);
  const colours = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e'];
  const parts = [`<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" font-family="sans-serif" font-size="11">`, `<rect width="${W}" height="${H}" fill="white"/>`];
  for (let e = y0; e <= y1; e++) {
    const y = py(10 ** e);
    parts.push(`<line x1="${L}" x2="${W - 150}" y1="${y}" y2="${y}" stroke="#ddd"/><text x="${L - 6}" y="${y + 4}" text-anchor="end">${10 ** e >= 1000 ? `${10 ** (e - 3)} s` : `${10 ** e} ms`}</text>`);
  }
  for (const size of outputs) {
    const x = px(size * size);
    parts.push(`<line x1="${x}" x2="${x}" y1="20" y2="${H - B}" stroke="#eee"/><text x="${x}" y="${H - B + 14}" text-anchor="middle">${size}²</text>`);
  }
  parts.push(`<text x="${(W - 150 + L) / 2}" y="${H - 6}" text-anchor="middle">output size (log pixels)</text>`);
  Object.entries(results).forEach(([method, points], i) => {
    if (!points.length) return;
    const c = colours[i % colours.length];
    parts.push(`<polyline fill="none" stroke="${c}" stroke-width="2" points="${points.map((p) => `${px(p.pixels).toFixed(1)},${py(p.ms).toFixed(1)}`).join(' ')}"/>`);
    for (const p of points) parts.push(`<circle cx="${px(p.pixels).toFixed(1)}" cy="${py(p.ms).toFixed(1)}" r="3" fill="${c}"/>`);
    parts.push(`<text x="${W - 140}" y="${30 + i * 16}" fill="${c}">${METHODS[method]}</text>`);
  });
  parts.push('</svg>');
  if (existsSync(new URL('../www/', import.meta.url))) writeFileSync(svgPath, parts.join('\n'));
  console.log(`\nplot: ${svgPath}`);
}
