// The threaded entry point (`texsynth-wasm/threads`) takes the same calls as the default one:
// its sessions iterate and have run(), a run cancelled by an AbortSignal leaves the session and
// the pool usable, and the output is the single-threaded module's.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { api, render, sampleBytes, threadedBuilt } from './fixtures.mjs';

const OPTIONS = { outputWidth: 96, outputHeight: 96, placement: 'entire-patch', seed: 2 };

test('threaded sessions iterate and run(); a cancelled run leaves the session and the pool usable', { timeout: 120_000 }, async (t) => {
  if (!threadedBuilt) return t.skip('no threaded module in pkg/ (built without the nightly)');
  const lib = await import('../../pkg/threads.js');
  const bytes = sampleBytes('tiles_64');
  const single = new api.GraphcutTextures(api.Exemplar.fromBytes(bytes), OPTIONS);
  await single.run();
  const reference = render(single);
  const make = () => new lib.GraphcutTextures(lib.Exemplar.fromBytes(bytes), OPTIONS);

  const iterated = make();
  const kinds = [];
  for (const event of iterated) kinds.push(event.kind);
  assert.equal(kinds.at(-1), 'done');
  assert.ok(kinds.length > 2, `${kinds.length} steps`);
  assert.deepEqual(render(iterated), reference, 'iterated: the single-threaded bytes');

  const cancelled = make();
  const controller = new AbortController();
  let steps = 0;
  await assert.rejects(
    cancelled.run({ signal: controller.signal, onEvent: () => { if (++steps === 2) controller.abort(); } }),
    { name: 'AbortError' },
  );
  assert.equal(cancelled.done, false);
  const fresh = make();
  await fresh.run();
  assert.deepEqual(render(fresh), reference, 'a new session after the cancelled run');
  await cancelled.run();
  assert.deepEqual(render(cancelled), reference, 'the cancelled session, run on to the end');
  for (const s of [single, iterated, cancelled, fresh]) s.free();
});
