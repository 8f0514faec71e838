// Guided synthesis through the package: setGuides makes the output follow the target guide, and
// refuses guides of the wrong size, channels or weight, or after the first step, by name.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { api, tinyExemplar } from './fixtures.mjs';

/** A grey Exemplar of `w` x `h` whose value at (x, y) is `f(x, y)` in 0..255. */
function grey(w, h, f) {
  const rgba = new Uint8Array(w * h * 4);
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) {
    const v = f(x, y);
    rgba.set([v, v, v, 255], (y * w + x) * 4);
  }
  return api.Exemplar.fromRgba(rgba, w, h);
}

/** Mean red value of columns x0..x1 of an RGBA image `w` wide. */
function mean(rgba, w, x0, x1) {
  let [sum, n] = [0, 0];
  for (let i = 0; i < rgba.length / 4; i++) if (i % w >= x0 && i % w < x1) { sum += rgba[i * 4]; n++; }
  return sum / n;
}

test('the output follows a dark-to-bright target guide', () => {
  const exemplar = tinyExemplar(32, 'gravel_64');
  const rgba = exemplar.toRgba();
  const source = grey(32, 32, (x, y) => rgba[(y * 32 + x) * 4]);
  const target = grey(48, 48, (x) => (x < 24 ? 40 : 210));
  const options = { outputWidth: 48, outputHeight: 48, neighbourhoodSizes: [8, 4], histogramMatching: 0, completeness: 0, seed: 3 };
  const render = (guided) => {
    const s = new api.TextureOptimization(exemplar, options);
    if (guided) s.setGuides(source, target, 4);
    [...s];
    const out = new Uint8ClampedArray(48 * 48 * 4);
    s.renderInto(out);
    s.free();
    return out;
  };
  const [plain, guided] = [render(false), render(true)];
  assert.ok(mean(guided, 48, 32, 48) - mean(guided, 48, 0, 16) > 30, 'guided: the right is brighter');
  assert.ok(Math.abs(mean(plain, 48, 32, 48) - mean(plain, 48, 0, 16)) < 30, 'plain: no such difference');
  for (const o of [exemplar, source, target]) o.free();
});

test('bad guides are refused by name', () => {
  const exemplar = tinyExemplar(32);
  const s = new api.TextureOptimization(exemplar, { outputWidth: 24, outputHeight: 24, neighbourhoodSizes: [8, 4] });
  const [source, target] = [grey(32, 32, () => 9), grey(24, 24, () => 9)];
  assert.throws(() => s.setGuides(target, target, 1), /sourceGuide/);
  assert.throws(() => s.setGuides(source, source, 1), /targetGuide/);
  assert.throws(() => s.setGuides(source, target, -1), /guideWeight/);
  assert.throws(() => s.setGuides(source, target, NaN), /guideWeight/);
  s.setGuides(source, target, 1);
  assert.throws(() => s.addExemplar(exemplar), /guides/);
  s.step();
  assert.throws(() => s.setGuides(source, target, 1), /before the first step/);
  for (const o of [s, exemplar, source, target]) o.free();
});

test('several exemplars take a source guide each', () => {
  // Two exemplars with flat source guides of 0 and 255: a target guide dark on the left and
  // bright on the right draws the left from the first exemplar and the right from the second.
  const [a, b] = [tinyExemplar(32, 'gravel_64'), tinyExemplar(32, 'tiles_64')];
  const [ga, gb] = [grey(32, 32, () => 0), grey(32, 32, () => 255)];
  const target = grey(48, 40, (x) => (x < 24 ? 0 : 255));
  const s = new api.TextureOptimization(a, { outputWidth: 48, outputHeight: 40, neighbourhoodSizes: [8, 4], seed: 2 });
  assert.throws(() => s.addGuidedExemplar(b, gb), /setGuides/);
  s.setGuides(ga, target, 4);
  assert.throws(() => s.addExemplar(b), /addGuidedExemplar/);
  assert.throws(() => s.addGuidedExemplar(b, grey(16, 16, () => 0)), /sourceGuide.*16x16/);
  assert.equal(s.addGuidedExemplar(b, gb), 1);
  [...s];
  const sources = new Uint8ClampedArray(48 * 40 * 4);
  s.renderSourcesInto(sources);
  // The sources view colours each exemplar; count the pixels whose colour is the second's.
  const second = sources.slice(((40 >> 1) * 48 + 47) * 4, ((40 >> 1) * 48 + 47) * 4 + 4);
  const share = (x0, x1) => {
    let [same, n] = [0, 0];
    for (let i = 0; i < 48 * 40; i++) {
      if (i % 48 < x0 || i % 48 >= x1) continue;
      n++;
      if (second.every((v, k) => sources[i * 4 + k] === v)) same++;
    }
    return same / n;
  };
  assert.ok(share(0, 16) < 0.1 && share(32, 48) > 0.9, `second exemplar: left ${share(0, 16)}, right ${share(32, 48)}`);
  for (const o of [s, a, b, ga, gb, target]) o.free();
});

test('channel weights: a channel of weight 0 does not steer the matches', () => {
  // RGBA exemplars that differ only in alpha give the same colours when alpha weighs 0.
  const base = tinyExemplar(32, 'gravel_64').toRgba();
  const withAlpha = (seed) => {
    const rgba = base.slice();
    for (let i = 0; i < 32 * 32; i++) rgba[i * 4 + 3] = (i * 7919 * seed) % 251;
    return api.Exemplar.fromRgba(rgba, 32, 32);
  };
  const run = (exemplar, channelWeights) => {
    const s = new api.TextureOptimization(exemplar, { outputWidth: 40, outputHeight: 40, neighbourhoodSizes: [8, 4], start: 'patches', channelWeights });
    [...s];
    const out = new Uint8ClampedArray(40 * 40 * 4);
    s.renderInto(out);
    s.free();
    return out.filter((_, i) => i % 4 !== 3).join();
  };
  const [one, two] = [withAlpha(1), withAlpha(3)];
  assert.equal(one.channels, 4);
  assert.equal(run(one, [1, 1, 1, 0]), run(two, [1, 1, 1, 0]));
  assert.notEqual(run(one, [1, 1, 1, 1]), run(two, [1, 1, 1, 1]));
  assert.throws(() => new api.TextureOptimization(one, { channelWeights: [1, 1] }), /channelWeights.*\(4\)/);
  assert.throws(() => new api.TextureOptimization(one, { channelWeights: [0, 0, 0, 0] }), /channelWeights/);
  for (const o of [one, two]) o.free();
});
