// The demo page in headless Chromium: samples are decoded by wasm and drawn, bad files show an error.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { openDemo, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

test('a picked sample is drawn with exactly the pixels of the PNG', async () => {
  const { page } = demo;
  await page.click('button[data-sample="gravel_64"]');
  await page.waitForSelector('body[data-exemplar="gravel 64×64"]');
  // Oracle: the browser's own PNG decoder, independent of the wasm one.
  const diff = await page.evaluate(async () => {
    const shown = document.getElementById('exemplar-canvas');
    const img = new Image();
    img.src = './samples/gravel_64.png';
    await img.decode();
    const ref = document.createElement('canvas');
    ref.width = img.width;
    ref.height = img.height;
    const ctx = ref.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const want = ctx.getImageData(0, 0, ref.width, ref.height).data;
    const got = shown.getContext('2d').getImageData(0, 0, shown.width, shown.height).data;
    let max = 0;
    for (let i = 0; i < want.length; i++) max = Math.max(max, Math.abs(want[i] - got[i]));
    return { size: [shown.width, shown.height], max, distinct: new Set(got).size };
  });
  assert.deepEqual(diff.size, [64, 64]);
  assert.ok(diff.max <= 1, `largest channel difference ${diff.max}`);
  assert.ok(diff.distinct > 20, 'the canvas holds a texture, not a flat colour');
  assert.match(await page.textContent('#exemplar-info'), /64×64/);
});

test('a corrupt upload shows a readable error and keeps the exemplar', async () => {
  const { page } = demo;
  await page.setInputFiles('#upload', {
    name: 'broken.png',
    mimeType: 'image/png',
    buffer: Buffer.concat([Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]), Buffer.from('truncated')]),
  });
  await page.waitForSelector('#error:not([hidden])');
  const message = await page.textContent('#error');
  assert.match(message, /broken\.png: could not decode the image/);
  assert.match(await page.textContent('#exemplar-info'), /gravel 64×64/);
});

test('an uploaded valid image replaces the exemplar and clears the error', async () => {
  const { page, errors } = demo;
  const png = await page.evaluate(async () => {
    const r = await fetch('./samples/tiles_64.png');
    return Array.from(new Uint8Array(await r.arrayBuffer()));
  });
  await page.setInputFiles('#upload', { name: 'mine.png', mimeType: 'image/png', buffer: Buffer.from(png) });
  await page.waitForSelector('body[data-exemplar="mine.png"]');
  assert.equal(await page.isHidden('#error'), true);
  await page.click('button[data-sample="brick_128"]');
  await page.waitForSelector('body[data-exemplar="brick 128×128"]');
  await page.screenshot({ path: `${RESULTS}/page.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

// A panel that loads its input (the video demo clip, the merge's second image) may be left before
// the load ends; its elements are gone by then. A CI run failed on this race.
for (const { panel, url } of [
  { panel: 'video', url: '**/samples/clips/water.png' },
  { panel: 'merge', url: '**/samples/sand_128.png' },
]) {
  test(`leaving the ${panel} panel while its input loads raises no error`, async () => {
    const { page, errors } = demo;
    let release;
    const held = new Promise((resolve) => { release = resolve; });
    let requested = false;
    await page.route(url, async (route) => {
      requested = true;
      await held;
      await route.continue();
    });
    await page.click(`#tab-${panel}`);
    await page.click('#tab-optimization');
    release();
    // The held load now ends with the optimization panel showing; give its continuation time.
    await page.waitForTimeout(500);
    await page.unroute(url);
    assert.ok(requested, `the ${panel} panel asked for ${url}`);
    assert.deepEqual(errors, []);
  });
}
