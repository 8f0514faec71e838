// Speed-up of the threaded module over its own one-thread pool, in Node: for each case, runs at 1
// thread and at every thread of this machine, interleaved (1, n, 1, n, ...) in one process, and
// prints one JSON line per case with the median times, the speed-up, whether the outputs are
// byte-identical, and the speed-up Amdahl's law projects for 8 threads from the measured serial
// fraction (s = (n/S - 1) / (n - 1) for speed-up S on n threads).
//
// node scripts/bench-threads.mjs [--rounds 3] [--cases graphcut:1024,optimization:1024,flow:512]
// Needs the threaded build (./scripts/build.sh with the pinned nightly: pkg/threads/).
import { existsSync, readFileSync } from 'node:fs';
import { availableParallelism } from 'node:os';
import { performance } from 'node:perf_hooks';
import { makeSession } from './lib/bench-sessions.mjs';

const ROOT = new URL('../', import.meta.url);
const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const rounds = Number(arg('rounds', 3));
const cases = arg('cases', 'graphcut:1024,optimization:1024,flow:512')
  .split(',')
  .map((c) => {
    const [method, size] = c.split(':');
    return { method, size: Number(size) };
  });

if (!existsSync(new URL('pkg/threads/texsynth_bg.wasm', ROOT))) {
  console.error('bench-threads: pkg/threads/ is missing; ./scripts/build.sh builds it with the pinned nightly');
  process.exit(1);
}
process.env.TEXSYNTH_THREADS = '1';
const lib = await import(new URL('pkg/threads.js', ROOT));
const all = availableParallelism();
const exemplar = lib.Exemplar.fromBytes(readFileSync(new URL('www/samples/tiles_128.png', ROOT)));

function fnv1a(bytes) {
  let h = 0x811c9dc5;
  for (const b of bytes) h = Math.imul(h ^ b, 0x01000193) >>> 0;
  return h.toString(16).padStart(8, '0');
}

function run(method, size) {
  const session = makeSession(lib, method, exemplar, size, 3);
  const start = performance.now();
  for (;;) {
    const event = session.step();
    if (event.done) break;
  }
  const ms = performance.now() - start;
  const out = new Uint8ClampedArray(session.width * session.height * 4);
  session.renderInto(out);
  session.free();
  return { ms, hash: fnv1a(out) };
}

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

for (const { method, size } of cases) {
  const times = { 1: [], [all]: [] };
  const hashes = new Set();
  for (let r = 0; r < rounds; r++) {
    for (const threads of [1, all]) {
      await lib.initThreadPool(threads);
      const { ms, hash } = run(method, size);
      times[threads].push(ms);
      hashes.add(hash);
    }
  }
  const one = median(times[1]);
  const many = median(times[all]);
  const speedup = one / many;
  const serial = all > 1 ? Math.min(1, Math.max(0, (all / speedup - 1) / (all - 1))) : 1;
  console.log(JSON.stringify({
    method,
    output: `${size}x${size}`,
    environment: 'node',
    threads: all,
    ms1: Math.round(one),
    msN: Math.round(many),
    speedup: Number(speedup.toFixed(2)),
    serialFraction: Number(serial.toFixed(3)),
    projected8: Number((1 / (serial + (1 - serial) / 8)).toFixed(2)),
    identical: hashes.size === 1,
    rounds,
  }));
}
process.exit(0);
