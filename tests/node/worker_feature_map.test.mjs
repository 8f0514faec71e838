// A feature map detected and edited in a worker, handed to FeatureSynthesis.withFeatureMap there
// by reference ({ ref }): the same map, the same synthesis and the same broken-feature count as
// the same calls made on the main thread.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { api, sampleBytes } from './fixtures.mjs';

const DETECT = { features: 'ridges', threshold: 0.9 };
const OPTIONS = { outputWidth: 96, outputHeight: 96, patchSize: 32, seed: 3, ...DETECT };
// A stroke across the exemplar and an erased band, in one move each.
const EDITS = [[4, 6, 58, 40, 0.6, true], [30, 0, 30, 63, 2.5, false]];

test('a worker FeatureMap is edited, feeds withFeatureMap by reference and counts broken features', { timeout: 120_000 }, async () => {
  const { createWorker } = await import('../../pkg/worker-node.js');
  const worker = createWorker();
  const other = createWorker();
  const exemplar = api.Exemplar.fromBytes(sampleBytes('brick_64'));
  const local = new api.FeatureMap(exemplar, DETECT);
  try {
    const detected = api.detectFeatures(exemplar, DETECT);
    assert.deepEqual(local.toMask(), detected.toMask(), 'the constructor is detectFeatures');
    detected.free();
    const remote = await worker.createSession('FeatureMap', exemplar, DETECT);
    assert.equal(await remote.call('count'), local.count);
    const before = local.count;
    for (const edit of EDITS) {
      local.paintLine(...edit);
      await remote.call('paintLine', ...edit);
    }
    assert.notEqual(local.count, before, 'the edits changed the map');
    const mask = await remote.call('toMask');
    assert.deepEqual(mask, local.toMask(), 'the same edits, the same map');
    assert.equal(await remote.call('count'), local.count);
    const view = await remote.render('renderInto');
    const here = new Uint8ClampedArray(64 * 64 * 4);
    local.renderInto(here);
    assert.deepEqual(view.data, here);

    // The synthesis from the worker's map by reference, against the one from the local map.
    const synthesis = await worker.createSession('FeatureSynthesis.withFeatureMap', exemplar, remote, OPTIONS);
    await synthesis.run({ render: null });
    const { data } = await synthesis.render('renderInto');
    const mine = api.FeatureSynthesis.withFeatureMap(exemplar, local, OPTIONS);
    while (!mine.done) mine.step();
    const expected = new Uint8ClampedArray(96 * 96 * 4);
    mine.renderInto(expected);
    mine.free();
    assert.deepEqual(data, expected, 'the edited map guided the worker synthesis');

    // brokenFeatures: measureBrokenFeatures against the exemplar as detected, edits or not.
    const broken = await remote.call('brokenFeatures', data, 96, 96);
    assert.equal(broken, api.measureBrokenFeatures(exemplar, data, 96, 96, DETECT));
    assert.equal(broken, local.brokenFeatures(data, 96, 96));
    assert.ok(Number.isFinite(broken));

    // Wrong references are errors that name the problem.
    await assert.rejects(worker.createSession('FeatureSynthesis.noSuchThing', exemplar, remote, OPTIONS), /FeatureSynthesis has no static constructor 'noSuchThing'/);
    await assert.rejects(worker.createSession('FeatureSynthesis.withFeatureMap.x', exemplar, remote), /unknown session kind/);
    await assert.rejects(other.createSession('FeatureSynthesis.withFeatureMap', exemplar, remote, OPTIONS), /lives in another worker/);
    await remote.free();
    await assert.rejects(worker.createSession('FeatureSynthesis.withFeatureMap', exemplar, remote, OPTIONS), /no object \d+ in this worker/);
    await assert.rejects(worker.createSession('FeatureSynthesis.withFeatureMap', exemplar, synthesis, OPTIONS), /FeatureMap/);
    await synthesis.free();
  } finally {
    local.free();
    exemplar.free();
    worker.terminate();
    other.terminate();
  }
});
