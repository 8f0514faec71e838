// Inpainting and uncrop through the package, as a JS user calls them: the known pixels come back
// byte for byte, the hole is filled by the fill and then the optimisation, every step reports,
// and bad masks and borders are refused by name.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { api, sampleBytes } from './fixtures.mjs';

const image = () => api.Exemplar.fromBytes(sampleBytes('brick_64'));

/** A centred square hole of about `share` of a `w` x `h` image. */
function hole(w, h, share) {
  const side = Math.floor(Math.sqrt(w * h * share));
  const [x0, y0] = [Math.floor((w - side) / 2), Math.floor((h - side) / 2)];
  const mask = new Uint8Array(w * h);
  for (let y = y0; y < y0 + side; y++) mask.fill(255, y * w + x0, y * w + x0 + side);
  return mask;
}

test('the known pixels come back byte for byte and the hole is filled', () => {
  const img = image();
  const { width: w, height: h } = img;
  const mask = hole(w, h, 0.4);
  const session = new api.Inpainting(img, mask, { seed: 2 });
  const events = [...session];
  assert.equal(events.at(-1).kind, 'done');
  const fill = events.filter((e) => e.stage === 'fill');
  assert.ok(fill.length > 1 && fill.every((e) => e.kind === 'placed' || e.kind === 'done'));
  assert.equal(fill.at(-1).pixelsFilled, fill.at(-1).holePixels);
  assert.ok(fill.every((e, i) => i === 0 || e.pixelsFilled >= fill[i - 1].pixelsFilled));
  const optimisation = events.filter((e) => e.stage === 'optimization');
  assert.ok(optimisation.some((e) => typeof e.energy === 'number' && e.level !== null));
  const out = new Uint8ClampedArray(w * h * 4);
  session.renderInto(out);
  const original = img.toRgba();
  let changed = 0;
  for (let i = 0; i < w * h; i++) {
    const same = [0, 1, 2, 3].every((k) => out[i * 4 + k] === original[i * 4 + k]);
    if (!mask[i]) assert.ok(same, `known pixel ${i} changed`);
    else if (!same) changed++;
  }
  assert.ok(changed > mask.filter(Boolean).length / 2, `only ${changed} hole pixels differ from the input`);
  const r = session.region;
  assert.ok(r.x >= 0 && r.x + r.width <= w && r.y + r.height <= h);
  session.free();
  img.free();
});

test('uncrop is extendBorder and the same session', () => {
  const img = image();
  const { image: big, mask } = api.extendBorder(img, { left: 16, bottom: 8 });
  assert.equal(big.width, img.width + 16);
  assert.equal(big.height, img.height + 8);
  assert.equal(mask.filter(Boolean).length, big.width * big.height - img.width * img.height);
  const session = new api.Inpainting(big, mask, { optimize: false });
  session.run && [...session];
  assert.ok(session.done);
  const out = new Uint8ClampedArray(big.width * big.height * 4);
  session.renderInto(out);
  const original = img.toRgba();
  for (let y = 0; y < img.height; y += 7) {
    for (let x = 0; x < img.width; x += 5) {
      const [i, j] = [(y * big.width + x + 16) * 4, (y * img.width + x) * 4];
      assert.deepEqual([...out.subarray(i, i + 4)], [...original.subarray(j, j + 4)]);
    }
  }
  // The border is texture, not the zeros extendBorder put there.
  const corner = out.subarray(0, 4);
  assert.notDeepEqual([...corner.subarray(0, 3)], [0, 0, 0]);
  session.free();
  big.free();
  img.free();
});

test('a separate exemplar fills the hole, and the same seed gives the same bytes', () => {
  const img = image();
  const exemplar = api.Exemplar.fromBytes(sampleBytes('gravel_64'));
  const mask = hole(img.width, img.height, 0.25);
  const render = () => {
    const s = api.Inpainting.withExemplar(img, mask, exemplar, { seed: 5 });
    [...s];
    const out = new Uint8ClampedArray(img.width * img.height * 4);
    s.renderInto(out);
    s.free();
    return out;
  };
  assert.deepEqual(render(), render());
  exemplar.free();
  img.free();
});

test('bad masks and borders are refused by name', () => {
  const img = image();
  const n = img.width * img.height;
  assert.throws(() => new api.Inpainting(img, new Uint8Array(n - 1), {}), /mask/);
  assert.throws(() => new api.Inpainting(img, new Uint8Array(n), {}), /mask: is empty/);
  assert.throws(() => new api.Inpainting(img, new Uint8Array(n).fill(1), {}), /mask: is full/);
  assert.throws(() => new api.Inpainting(img, hole(img.width, img.height, 0.2), { patchSize: 1 }), /patchSize/);
  assert.throws(() => api.extendBorder(img, 0), /border/);
  assert.throws(() => api.extendBorder(img, -3), /border/);
  assert.throws(() => api.extendBorder(img, { top: 2, middle: 3 }), /middle/);
  assert.throws(() => api.extendBorder(img, { top: 1.5 }), /border.top/);
  assert.throws(() => api.extendBorder(img, 'wide'), /border/);
  img.free();
});
