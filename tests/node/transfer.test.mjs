// Material sets through the package: transferInto re-indexes another image of the exemplar's
// size by the output's source map (graph cut's transfer of the exemplar is its output, byte for
// byte), and refuses what has no map.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { api, tinyExemplar } from './fixtures.mjs';

/** A normal map from an exemplar's luminance (central differences), as RGB bytes. */
function normalMap(exemplar) {
  const { width: w, height: h } = exemplar;
  const rgba = exemplar.toRgba();
  const lum = (x, y) => {
    const i = (Math.min(h - 1, Math.max(0, y)) * w + Math.min(w - 1, Math.max(0, x))) * 4;
    return (0.299 * rgba[i] + 0.587 * rgba[i + 1] + 0.114 * rgba[i + 2]) / 255;
  };
  const out = new Uint8Array(w * h * 4);
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      const [dx, dy] = [(lum(x + 1, y) - lum(x - 1, y)) * 4, (lum(x, y + 1) - lum(x, y - 1)) * 4];
      const n = Math.hypot(dx, dy, 1);
      out.set([(-dx / n + 1) * 127.5, (-dy / n + 1) * 127.5, (1 / n + 1) * 127.5, 255], (y * w + x) * 4);
    }
  }
  return api.Exemplar.fromRgba(out, w, h);
}

test('graph cut: the exemplar transferred is the output, and a normal map stays unit length', () => {
  const exemplar = tinyExemplar(32, 'tiles_64');
  const session = new api.GraphcutTextures(exemplar, { outputWidth: 48, outputHeight: 40, seed: 4 });
  [...session];
  const [output, transferred] = [new Uint8ClampedArray(48 * 40 * 4), new Uint8ClampedArray(48 * 40 * 4)];
  session.renderInto(output);
  session.transferInto(exemplar, transferred);
  assert.deepEqual(transferred, output);
  const normals = normalMap(exemplar);
  session.transferInto(normals, transferred);
  for (let i = 0; i < 48 * 40; i++) {
    const v = [0, 1, 2].map((k) => transferred[i * 4 + k] / 127.5 - 1);
    assert.ok(Math.abs(Math.hypot(...v) - 1) < 0.02, `pixel ${i}: |n| = ${Math.hypot(...v)}`);
  }
  const wrong = tinyExemplar(16);
  assert.throws(() => session.transferInto(wrong, transferred), /exemplar's size, 32x32/);
  assert.throws(() => session.transferInto(normals, new Uint8ClampedArray(5)), /target/);
  for (const o of [session, exemplar, normals, wrong]) o.free();
});

test('texture optimisation: a map once the finest level ran, none before', () => {
  const exemplar = tinyExemplar(32);
  const session = new api.TextureOptimization(exemplar, { outputWidth: 40, outputHeight: 40, neighbourhoodSizes: [8, 4], iterations: 2 });
  const target = new Uint8ClampedArray(40 * 40 * 4);
  assert.throws(() => session.transferInto(exemplar, target), /finest level/);
  [...session];
  session.transferInto(exemplar, target);
  assert.ok(target.some((v, i) => i % 4 !== 3 && v !== 0));
  session.free();
  exemplar.free();
});

test('graph cut with rotated sources has no map', () => {
  const exemplar = tinyExemplar(32);
  const session = new api.GraphcutTextures(exemplar, { outputWidth: 32, outputHeight: 32, rotate: true });
  assert.throws(() => session.transferInto(exemplar, new Uint8ClampedArray(32 * 32 * 4)), /sources/);
  session.free();
  exemplar.free();
});
