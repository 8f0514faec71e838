// The wasm half of scripts/compare.sh: times texsynth's methods as the wasm package in Node on
// exactly the runs the native `compare` binary planned: the single-threaded module when the plan
// asks for one thread, else the threaded module (pkg/threads/) on a pool of that many threads.
// Usage: node scripts/compare_wasm.mjs results/compare/plan.json   (writes wasm.json beside it)
//
// The plan (written by `compare --prepare-only`) lists the prepared exemplar PNGs with the hash
// of their bytes, the output size, the seeds, and per method the session class and options. The
// exemplars are decoded by the package's own Exemplar.fromBytes, the same decoder the native run
// uses, so both see the same pixels; the hashes of the bytes and of every output go back so the
// native side can check that and tell whether wasm produced the very same image.
import { existsSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { performance } from 'node:perf_hooks';

const planPath = process.argv[2];
if (!planPath) {
  console.error('usage: node scripts/compare_wasm.mjs PLAN.json  (see scripts/compare.sh)');
  process.exit(2);
}
const plan = JSON.parse(readFileSync(planPath, 'utf8'));
const [width, height] = plan.size;

const threads = plan.threads ?? 1;
let texsynth;
let wasmUrl;
if (threads > 1) {
  wasmUrl = new URL('../pkg/threads/texsynth_bg.wasm', import.meta.url);
  if (!existsSync(wasmUrl)) {
    console.error('compare_wasm: pkg/threads/ is missing; ./scripts/build.sh builds it with the pinned nightly');
    process.exit(1);
  }
  process.env.TEXSYNTH_THREADS = String(threads);
  texsynth = await import('../pkg/threads.js');
  const size = await texsynth.initThreadPool(threads);
  if (size !== threads) throw new Error(`the thread pool has ${size} threads, not ${threads}`);
} else {
  wasmUrl = new URL('../pkg/texsynth_bg.wasm', import.meta.url);
  texsynth = await import('../pkg/texsynth.js');
  await texsynth.default({ module_or_path: readFileSync(wasmUrl) });
}

/** 32-bit FNV-1a as 8 hex digits, as bench/src/prepare.rs computes it. */
function fnv1a(bytes) {
  let h = 0x811c9dc5;
  for (let i = 0; i < bytes.length; i++) {
    h ^= bytes[i];
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h.toString(16).padStart(8, '0');
}

/**
 * One timed run: session construction plus every step (as the native run times it); rendering
 * the output for its hash comes after the clock stops.
 */
function runOnce(exemplar, method, seed) {
  const Session = texsynth[method.class];
  if (typeof Session !== 'function') throw new Error(`the package has no ${method.class}`);
  const start = performance.now();
  const session = new Session(exemplar, { ...method.options, outputWidth: width, outputHeight: height, seed });
  let steps = 0;
  let maxStep = 0;
  try {
    for (;;) {
      const t = performance.now();
      const event = session.step();
      maxStep = Math.max(maxStep, performance.now() - t);
      steps++;
      if (event.done) break;
    }
    const total = performance.now() - start;
    const rgba = new Uint8ClampedArray(session.width * session.height * 4);
    session.renderInto(rgba);
    return { total_ms: total, steps, max_step_ms: maxStep, output_hash: fnv1a(rgba) };
  } finally {
    session.free();
  }
}

const runs = [];
for (const [i, ex] of plan.exemplars.entries()) {
  const bytes = readFileSync(ex.png);
  const hash = fnv1a(bytes);
  if (hash !== ex.hash) {
    console.error(`compare_wasm: ${ex.png} changed since the plan was written; rerun scripts/compare.sh`);
    process.exit(1);
  }
  const exemplar = texsynth.Exemplar.fromBytes(bytes);
  console.error(`[wasm ${i + 1}/${plan.exemplars.length}] ${ex.name} (${exemplar.width}x${exemplar.height})`);
  for (const method of plan.methods) {
    for (const seed of plan.seeds) {
      const run = { exemplar: ex.name, exemplar_hash: hash, method: method.name, seed };
      try {
        Object.assign(run, runOnce(exemplar, method, seed));
        console.error(`  ${method.name.padEnd(16)} seed ${String(seed).padEnd(3)} ${run.total_ms.toFixed(1).padStart(9)} ms  ${run.steps} steps`);
      } catch (e) {
        run.error = String(e?.message ?? e);
        console.error(`  ${method.name.padEnd(16)} seed ${String(seed).padEnd(3)} failed: ${run.error}`);
      }
      runs.push(run);
    }
  }
  exemplar.free();
}

const out = join(dirname(planPath), 'wasm.json');
const result = { node: process.version, wasm_bytes: statSync(wasmUrl).size, size: [width, height], threads, runs };
writeFileSync(out, JSON.stringify(result, null, 2));
console.error(`compare_wasm: wrote ${out}`);
