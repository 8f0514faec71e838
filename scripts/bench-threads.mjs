// Speed-up of the threaded module over its own one-thread pool, in Node and in headless Chromium:
// for each case, runs at 1 thread and at every thread of this machine, interleaved (1, n, 1, n,
// ...), and prints one JSON line per case and environment with the median times, the speed-up,
// whether the outputs are byte-identical, and the speed-up Amdahl's law projects for 8 threads
// from the measured serial fraction (s = (n/S - 1) / (n - 1) for speed-up S on n threads).
//
// In Node the sessions run in this process, one step at a time, and the time of each step is
// put down to the phase it ran (texture optimisation and flow animation step half an EM
// iteration at a time: the start, a level's first M-step, E-steps with histogram matching,
// M-steps); `phases` gives each phase's share of the one-thread time and its own speed-up, and
// `serialPhases` names those that gain less than 1.2x. In Chromium the page as
// ./scripts/build-site.sh writes it is served cross-origin isolated, and each session runs in a
// worker of the package's worker wrapper, `createWorker({ threads })`: the page's own build.
//
// node scripts/bench-threads.mjs [--rounds 3] [--cases graphcut:1024,optimization:1024,flow:512]
//                                [--environments node,chromium]
// Needs the threaded build (./scripts/build.sh with the pinned nightly: pkg/threads/) and, for
// Chromium, site/ (./scripts/build-site.sh).
import { existsSync, readFileSync } from 'node:fs';
import { availableParallelism } from 'node:os';
import { performance } from 'node:perf_hooks';
import { sessionSpec } from './lib/bench-sessions.mjs';

const ROOT = new URL('../', import.meta.url);
const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const rounds = Number(arg('rounds', 3));
const FLOW_FRAMES = 3;
const SAMPLE = 'tiles_128';
const cases = arg('cases', 'graphcut:1024,optimization:1024,flow:512')
  .split(',')
  .map((c) => {
    const [method, size] = c.split(':');
    return { method, size: Number(size) };
  });
const environments = arg('environments', 'node,chromium').split(',');

if (!existsSync(new URL('pkg/threads/texsynth_bg.wasm', ROOT))) {
  console.error('bench-threads: pkg/threads/ is missing; ./scripts/build.sh builds it with the pinned nightly');
  process.exit(1);
}
const all = availableParallelism();
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const round = (x, digits) => Number(x.toFixed(digits));

function fnv1a(bytes) {
  let h = 0x811c9dc5;
  for (const b of bytes) h = Math.imul(h ^ b, 0x01000193) >>> 0;
  return h.toString(16).padStart(8, '0');
}

/** The JSON line of one case: `times` and `phases` keyed by thread count (1 and all). */
function report(method, size, environment, times, hashes, phases) {
  const one = median(times[1]);
  const many = median(times[all]);
  const speedup = one / many;
  const serial = all > 1 ? Math.min(1, Math.max(0, (all / speedup - 1) / (all - 1))) : 1;
  const line = {
    method,
    output: `${size}x${size}`,
    environment,
    threads: all,
    ms1: Math.round(one),
    msN: Math.round(many),
    speedup: round(speedup, 2),
    serialFraction: round(serial, 3),
    projected8: round(1 / (serial + (1 - serial) / 8), 2),
    identical: hashes.size === 1,
    rounds,
  };
  if (phases) {
    const total = Object.values(phases[1]).reduce((a, b) => a + b, 0);
    line.phases = Object.fromEntries(Object.keys(phases[1]).map((name) => [name, {
      share: round(phases[1][name] / total, 3),
      speedup: round(phases[1][name] / Math.max(1e-9, phases[all][name] ?? 0), 2),
    }]));
    line.serialPhases = Object.entries(line.phases).filter(([, p]) => p.speedup < 1.2).map(([name]) => name);
  }
  console.log(JSON.stringify(line));
}

/** The phase a step ran, from its event: graph cut's steps are patch placements. */
const phaseOf = (event) => {
  if (event.kind === 'part') return event.phase;
  if (event.kind === 'iteration' || event.kind === 'level' || event.kind === 'done') return event.phase ?? 'm-step';
  return event.kind;
};

async function inNode() {
  process.env.TEXSYNTH_THREADS = '1';
  const lib = await import(new URL('pkg/threads.js', ROOT));
  const exemplar = lib.Exemplar.fromBytes(readFileSync(new URL(`www/samples/${SAMPLE}.png`, ROOT)));
  const run = (method, size, phases) => {
    const { kind, options } = sessionSpec(method, size, FLOW_FRAMES);
    const session = new lib[kind](exemplar, options);
    session.setHalfSteps?.(true);
    let ms = 0;
    for (;;) {
      const start = performance.now();
      const event = session.step();
      const took = performance.now() - start;
      ms += took;
      const phase = phaseOf(event);
      phases[phase] = (phases[phase] ?? 0) + took;
      if (event.done) break;
    }
    const out = new Uint8ClampedArray(session.width * session.height * 4);
    session.renderInto(out);
    session.free();
    return { ms, hash: fnv1a(out) };
  };
  for (const { method, size } of cases) {
    const times = { 1: [], [all]: [] };
    const phases = { 1: {}, [all]: {} };
    const hashes = new Set();
    for (let r = 0; r < rounds; r++) {
      for (const threads of [1, all]) {
        await lib.initThreadPool(threads);
        const { ms, hash } = run(method, size, phases[threads]);
        times[threads].push(ms);
        hashes.add(hash);
      }
    }
    report(method, size, 'node', times, hashes, method === 'graphcut' ? null : phases);
  }
}

async function inChromium() {
  if (!existsSync(new URL('site/pkg/threads/texsynth_bg.wasm', ROOT))) {
    console.error('bench-threads: site/pkg/threads/ is missing; ./scripts/build-site.sh writes it');
    process.exit(1);
  }
  const { chromium } = await import('playwright-core');
  const { startServer } = await import('./serve.mjs');
  const server = await startServer({ port: 0, isolated: true });
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage'],
  });
  try {
    const page = await browser.newPage();
    await page.goto(`http://127.0.0.1:${server.address().port}/samples/`).catch(() => {});
    await page.goto(`http://127.0.0.1:${server.address().port}/index.html`);
    for (const { method, size } of cases) {
      const spec = sessionSpec(method, size, FLOW_FRAMES);
      const result = await page.evaluate(async ({ spec, all, rounds, sample }) => {
        const { createWorker } = await import('/pkg/worker.js');
        const bytes = new Uint8Array(await (await fetch(`/samples/${sample}.png`)).arrayBuffer());
        const workers = { 1: createWorker({ threads: 1 }), [all]: createWorker({ threads: all }) };
        const info = { 1: await workers[1].ready, [all]: await workers[all].ready };
        const times = { 1: [], [all]: [] };
        const hashes = [];
        for (let r = 0; r < rounds; r++) {
          for (const threads of [1, all]) {
            const session = await workers[threads].createSession(spec.kind, { bytes: bytes.slice() }, spec.options);
            const start = performance.now();
            await session.run({ render: null });
            times[threads].push(performance.now() - start);
            const { data } = await session.render('renderInto');
            let h = 0x811c9dc5;
            for (const b of data) h = Math.imul(h ^ b, 0x01000193) >>> 0;
            hashes.push(h);
            await session.free();
          }
        }
        for (const w of Object.values(workers)) w.terminate();
        return { times, hashes, info };
      }, { spec, all, rounds, sample: SAMPLE });
      if (!result.info[all].threaded || result.info[all].threads !== all) {
        throw new Error(`the page's worker did not run ${all} threads: ${JSON.stringify(result.info[all])}`);
      }
      report(method, size, 'chromium', result.times, new Set(result.hashes), null);
    }
  } finally {
    await browser.close();
    server.close();
  }
}

if (environments.includes('node')) await inNode();
if (environments.includes('chromium')) await inChromium();
process.exit(0);
