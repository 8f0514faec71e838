// Run by leaks.test.mjs as `node --expose-gc leak_run.mjs MODE COUNT`: for every session type of
// sessions.mjs, COUNT sessions are made from one shared input, stepped twice and then freed
// (MODE 'free') or simply dropped for wasm-bindgen's FinalizationRegistry to free after a
// garbage collection (MODE 'drop'). Prints one JSON line per type: the wasm memory size after
// the first 10 sessions and at the end, in bytes (wasm memory only grows, so a leak shows as
// growth).
import { api, sampleBytes } from './fixtures.mjs';
import { SESSIONS, exercise, inputFor } from './sessions.mjs';

const [mode = 'free', countArg = '1000'] = process.argv.slice(2);
const count = Number(countArg);
if (typeof globalThis.gc !== 'function') throw new Error('run with node --expose-gc');
// Already loaded: initSync returns the exports. The threaded module imports its shared memory
// rather than exporting it; its pool hands it out.
const memory = api.initSync(sampleBytes()).memory ?? api.threadPoolMemory?.() ?? null;
if (!memory) throw new Error('the package exports no memory');

/** Collects garbage and lets the FinalizationRegistry callbacks run (they are queued tasks). */
async function collect(rounds = 1) {
  for (let i = 0; i < rounds; i++) {
    globalThis.gc();
    await new Promise((resolve) => setImmediate(resolve));
  }
}

for (const [kind, spec] of Object.entries(SESSIONS)) {
  const input = inputFor(kind);
  const probe = spec.make({}, input);
  if (typeof probe?.free !== 'function') continue; // plain results (numbers, arrays) hold nothing
  probe.free();
  const drive = spec.exercise ?? ((s) => typeof s.step === 'function' && exercise(s, 2));
  let afterTen = 0;
  const start = performance.now();
  for (let i = 0; i < count; i++) {
    const session = spec.make({}, input);
    drive(session);
    if (mode === 'free') session.free();
    // Dropped sessions are freed only after a collection: collect every 10, so that at most as
    // many are alive at once as when the baseline is taken (after the first 10).
    if (mode === 'drop' && i % 10 === 9) await collect();
    if (i === 9) {
      await collect(3);
      afterTen = memory.buffer.byteLength;
    }
  }
  await collect(3);
  input.free();
  const end = memory.buffer.byteLength;
  console.log(JSON.stringify({ kind, mode, count, afterTen, end, growth: end - afterTen, ms: Math.round(performance.now() - start) }));
}
