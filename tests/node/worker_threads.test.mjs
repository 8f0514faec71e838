// The worker wrapper's `threads` option over worker_threads: 'auto' runs the threaded module on
// every core (or, in a build without it, the single-threaded one with the reason), a count runs
// that many threads (or fails, naming why), false runs the single-threaded module, and anything
// else is refused. Every choice makes the same bytes.
import { existsSync } from 'node:fs';
import { availableParallelism } from 'node:os';
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { api, sampleBytes } from './fixtures.mjs';

const built = existsSync(new URL('../../pkg/threads/texsynth_bg.wasm', import.meta.url));

async function outputOf(worker, exemplar) {
  const session = await worker.createSession('TextureOptimization', exemplar, { outputWidth: 48, outputHeight: 40, seed: 5, levels: 2 });
  await session.run({ render: null });
  const { data } = await session.render('renderInto');
  await session.free();
  return data;
}

test('threads picks the worker module; every choice makes the same bytes', { timeout: 300_000 }, async () => {
  const { createWorker } = await import('../../pkg/worker-node.js');
  const exemplar = api.Exemplar.fromBytes(sampleBytes('gravel_64'));
  const outputs = [];
  try {
    for (const [threads, want] of [
      [false, { threaded: false, threads: 1, reason: null }],
      ['auto', built
        ? { threaded: true, threads: availableParallelism(), reason: null }
        : { threaded: false, threads: 1, reason: 'this package has no threaded module (it was built without the nightly toolchain)' }],
      [2, built ? { threaded: true, threads: 2, reason: null } : null],
      [1, built ? { threaded: true, threads: 1, reason: null } : null],
    ]) {
      const worker = createWorker({ threads });
      try {
        if (want === null) {
          await assert.rejects(worker.ready, new RegExp(`could not start: ${threads} threads were asked for, but this package has no threaded module`));
          continue;
        }
        assert.deepEqual(await worker.ready, want, `threads: ${threads}`);
        assert.deepEqual(worker.info, want);
        outputs.push([threads, await outputOf(worker, exemplar)]);
      } finally {
        worker.terminate();
      }
    }
  } finally {
    exemplar.free();
  }
  for (const [threads, data] of outputs.slice(1)) assert.deepEqual(data, outputs[0][1], `threads: ${threads}`);
  for (const bad of [0, 65, 2.5, 'two', true, null]) {
    assert.throws(() => createWorker({ threads: bad }), /threads must be 'auto', false or a whole number from 1 to 64/);
  }
  const { createPool } = await import('../../pkg/worker-node.js');
  const pool = createPool(1);
  try {
    assert.deepEqual(await pool.workers[0].ready, { threaded: false, threads: 1, reason: null }, 'a pool is single-threaded by default');
  } finally {
    pool.close();
  }
});
