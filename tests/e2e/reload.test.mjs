// Determinism across page reloads: the same sample, seed and options give the same pixels after
// the page is loaded again (a new wasm instance and Worker), for texture optimisation and graph cut.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createHash } from 'node:crypto';
import { canvasPixels, openDemo } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

/** Runs `panel` on tiles_64 to 80x80 from a freshly loaded page; returns a hash of the output. */
async function runFresh(page, panel, doneAttribute) {
  await page.reload();
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  await page.click(`button[data-panel="${panel}"]`);
  await page.click('button[data-sample="tiles_64"]');
  await page.waitForSelector('body[data-exemplar="tiles 64×64"]');
  await page.fill('#seed', '5');
  await page.dispatchEvent('#seed', 'change');
  await page.fill('#out-width', '80');
  await page.fill('#out-height', '80');
  await page.dispatchEvent('#out-height', 'change');
  await page.click('#run');
  await page.waitForSelector(`body[${doneAttribute}="true"]`, { timeout: 120_000 });
  const pixels = await canvasPixels(page, 'output-canvas');
  assert.equal(pixels.length, 80 * 80 * 4);
  return createHash('sha256').update(Uint8Array.from(pixels)).digest('hex');
}

test('a reload reproduces the same output pixels', async () => {
  const { page, errors } = demo;
  for (const [panel, done] of [['optimization', 'data-optimization-done'], ['graphcut', 'data-graphcut-done']]) {
    const first = await runFresh(page, panel, done);
    const second = await runFresh(page, panel, done);
    assert.equal(second, first, `${panel}: the same pixels after a reload`);
  }
  assert.deepEqual(errors, []);
});
