// A worker session's quality(): the whole output, or with `maxSide` its central window, scored
// exactly as measureQuality scores that window cut out by hand.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { api, sampleBytes } from './fixtures.mjs';

test('quality({ maxSide }) scores the central window and names it; a bad maxSide is an error', { timeout: 120_000 }, async () => {
  const { createWorker } = await import('../../pkg/worker-node.js');
  const worker = createWorker();
  const exemplar = api.Exemplar.fromBytes(sampleBytes('gravel_64'));
  try {
    const session = await worker.createSession('GraphcutTextures', exemplar, { outputWidth: 96, outputHeight: 80, seed: 2 });
    await session.run({ render: null });
    const { data } = await session.render('renderInto');
    const whole = await session.quality();
    assert.equal(whole.window, undefined);
    assert.deepEqual(whole, { ...api.measureQuality(exemplar, data, 96, 80) });

    const part = await session.quality({ maxSide: 48 });
    assert.deepEqual(part.window, { x: 24, y: 16, width: 48, height: 48 });
    const cut = new Uint8Array(48 * 48 * 4);
    for (let row = 0; row < 48; row++) cut.set(data.subarray(((16 + row) * 96 + 24) * 4, ((16 + row) * 96 + 72) * 4), row * 48 * 4);
    const expected = api.measureQuality(exemplar, cut, 48, 48);
    const { window, ...figures } = part;
    assert.deepEqual(figures, { ...expected });
    assert.notDeepEqual(figures, { ...whole }, 'the window is scored, not the whole output');

    assert.deepEqual(await session.quality({ maxSide: 96 }), whole, 'an output that fits is scored whole');
    for (const bad of [3, 10.5, 'a', Number.NaN]) {
      await assert.rejects(session.quality({ maxSide: bad }), /maxSide must be an integer of at least 7/);
    }
    await session.free();
  } finally {
    exemplar.free();
    worker.terminate();
  }
});
