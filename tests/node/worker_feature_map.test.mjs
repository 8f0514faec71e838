// A feature map detected and edited in a worker, handed to FeatureSynthesis.withFeatureMap there
// by reference ({ ref }): the same map, the same synthesis and the same broken-feature count as
// the same calls made on the main thread; and a graph-cut session there counts at seams against
// it by reference.
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

    // A graph-cut session of the worker counts the curves its seams cut against the worker's map
    // by reference (a photo's map stays there), as against the map's mask sent along.
    const gc = await worker.createSession('GraphcutTextures', exemplar, { outputWidth: 96, outputHeight: 96, seed: 3 });
    await gc.run({ render: null });
    const seams = await gc.call('carriedBrokenFeaturesOf', remote);
    assert.ok(Number.isFinite(seams));
    assert.equal(seams, await gc.call('carriedBrokenFeatures', mask));
    const foreign = await other.createSession('FeatureMap', exemplar, DETECT);
    await assert.rejects(gc.call('carriedBrokenFeaturesOf', foreign), /lives in another worker/);
    await assert.rejects(gc.call('carriedBrokenFeaturesOf', synthesis), /FeatureMap/);

    // Wrong references are errors that name the problem.
    await assert.rejects(worker.createSession('FeatureSynthesis.noSuchThing', exemplar, remote, OPTIONS), /FeatureSynthesis has no static constructor 'noSuchThing'/);
    await assert.rejects(worker.createSession('FeatureSynthesis.withFeatureMap.x', exemplar, remote), /unknown session kind/);
    await assert.rejects(other.createSession('FeatureSynthesis.withFeatureMap', exemplar, remote, OPTIONS), /lives in another worker/);
    await remote.free();
    await assert.rejects(worker.createSession('FeatureSynthesis.withFeatureMap', exemplar, remote, OPTIONS), /no object \d+ in this worker/);
    await assert.rejects(worker.createSession('FeatureSynthesis.withFeatureMap', exemplar, synthesis, OPTIONS), /FeatureMap/);
    await assert.rejects(gc.call('carriedBrokenFeaturesOf', remote), /no object \d+ in this worker/);
    await synthesis.free();
    await gc.free();
  } finally {
    local.free();
    exemplar.free();
    worker.terminate();
    other.terminate();
  }
});
