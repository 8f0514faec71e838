// Several exemplars through the package: addExemplar before the first step, the output drawn
// from all of them, and renderSourcesInto colouring each pixel by its exemplar.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { api, tinyExemplar } from './fixtures.mjs';

/** The distinct opaque colours of an RGBA view. */
function colours(rgba) {
  const seen = new Set();
  for (let i = 0; i < rgba.length; i += 4) if (rgba[i + 3]) seen.add((rgba[i] << 16) | (rgba[i + 1] << 8) | rgba[i + 2]);
  return seen;
}

for (const [kind, options] of [
  ['GraphcutTextures', { outputWidth: 96, outputHeight: 96, k: 10, seed: 2 }],
  ['TextureOptimization', { outputWidth: 64, outputHeight: 64, neighbourhoodSizes: [8, 4], iterations: 2, seed: 2 }],
]) {
  test(`${kind}: patches or matches from every exemplar, coloured by exemplar`, () => {
    const [a, b] = [tinyExemplar(32, 'gravel_64'), tinyExemplar(24, 'gravel_64')];
    const session = new api[kind](a, options);
    assert.equal(session.addExemplar(b), 1);
    const view = new Uint8ClampedArray(session.width * session.height * 4);
    session.renderSourcesInto(view);
    [...session];
    session.renderSourcesInto(view);
    assert.equal(colours(view).size, 2, 'both exemplars show');
    assert.throws(() => session.addExemplar(a), /before the first step/);
    session.free();
    a.free();
    b.free();
  });
}
