// The worker wrapper in Node (worker_threads): a pool of two running two jobs, and one session
// driven step by step with a teaching view and a cancelled run.
import { readFileSync } from 'node:fs';
import { createPool, createWorker } from 'texsynth-wasm/worker';

const bytes = readFileSync(process.argv[2]);
const pool = createPool(2);
const results = await Promise.all([1, 2].map((seed) =>
  pool.run('GraphcutTextures', [{ bytes }, { outputWidth: 64, outputHeight: 64, seed }])));
pool.close();

const worker = createWorker();
const session = await worker.createSession('TextureOptimization', { bytes }, { outputWidth: 64, outputHeight: 64 });
const first = await session.step();
const schedule = await session.call('schedule');
const offsets = await session.render('renderOffsetMapInto');
const controller = new AbortController();
let events = 0;
let aborted = '';
try {
  await session.run({ signal: controller.signal, onEvent: (event, image) => { if (++events === 2) controller.abort(); } });
} catch (error) {
  aborted = error.name;
}
const rest = await session.run({ render: null });
worker.terminate();
console.log(JSON.stringify({
  pool: results.map((r) => [r.event.done, r.image.width, r.image.data.length]),
  firstKind: first.event.kind, firstImage: first.image.data.length, levels: schedule.length,
  offsets: offsets.data.length, aborted, finished: rest.event.done,
}));
