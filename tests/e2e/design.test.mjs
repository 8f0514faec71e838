// The "Texture design" panel (Shen et al. 2009) in headless Chromium: a deformed set fills the
// gallery, a brush stroke changes the base and draws its labelling and seam, undo restores it,
// layer-based design runs to done, and make-tileable shows the 3x3 preview.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, openDemo, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

const redPixels = (pixels) => {
  let n = 0;
  for (let i = 0; i < pixels.length; i += 4) if (pixels[i] === 255 && pixels[i + 1] === 40 && pixels[i + 2] === 40) n++;
  return n;
};

test('stage 1 fills the gallery with deformed textures', async () => {
  const { page, errors } = demo;
  await page.click('button[data-panel="design"]');
  await page.click('button[data-sample="potatoes_64"]');
  await page.waitForSelector('body[data-exemplar="potatoes 64×64"]');
  await page.waitForSelector('body[data-gallery-count="1"]');
  // Run has nothing to do in this stage (its button makes the set): the status says so, rather
  // than "running…" with no step.
  await page.click('#run');
  await page.waitForFunction(() => document.getElementById('status').textContent.startsWith('nothing to run in Deform'), null, { timeout: 5_000 });
  assert.match(await page.textContent('#status'), /^nothing to run in Deform: choose ranges, then "Make deformed set"/);
  await page.click('#dd-make');
  await page.waitForSelector('body[data-deformed]');
  const count = Number(await page.getAttribute('body', 'data-gallery-count'));
  assert.ok(count >= 5, `gallery holds ${count}`);
  await page.screenshot({ path: `${RESULTS}/design-deform.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('stage 2: a stroke changes the base along a graph-cut seam, and undo restores it', async () => {
  const { page, errors } = demo;
  await page.click('button[data-stage="brush"]');
  // The reference: the mirrored sample (the last deformation of the set).
  const count = Number(await page.getAttribute('body', 'data-gallery-count'));
  await page.click(`.gallery-item[data-index="${count - 1}"] button[data-role="reference"]`);
  const before = await canvasPixels(page);
  const ref = await page.locator('#db-reference').boundingBox();
  await page.mouse.move(ref.x + ref.width * 0.4, ref.y + ref.height * 0.4);
  await page.mouse.down();
  await page.mouse.move(ref.x + ref.width * 0.55, ref.y + ref.height * 0.5, { steps: 5 });
  await page.mouse.up();
  const out = await page.locator('#output-canvas').boundingBox();
  await page.mouse.click(out.x + out.width * 0.5, out.y + out.height * 0.5);
  await page.waitForSelector('body[data-strokes="1"]');
  const after = await canvasPixels(page);
  assert.notDeepEqual(after, before, 'the stroke changed the base');
  assert.ok(redPixels(after) > 10, 'the seam is drawn');
  assert.match(await page.textContent('#ds-readout'), /pixels took the reference/);
  await page.screenshot({ path: `${RESULTS}/design-brush.png`, fullPage: true });
  // A new ν is for the strokes to come: the stroke made and its undo stay.
  await page.fill('#db-nu', '10');
  await page.dispatchEvent('#db-nu', 'change');
  assert.match(await page.textContent('#ds-readout'), /ν 10 for the next strokes/);
  assert.equal(await page.getAttribute('body', 'data-strokes'), '1');
  assert.deepEqual(await canvasPixels(page), after, 'the base keeps the stroke');
  await page.click('#db-undo');
  await page.waitForSelector('body[data-strokes="0"]');
  assert.deepEqual(await canvasPixels(page), before, 'undo restores the base');
  assert.deepEqual(errors, []);
});

test('stage 3: pixels, Haar and Daubechies energies run in turn and share one energy plot', async () => {
  const { page, errors } = demo;
  await page.click('button[data-stage="synthesis"]');
  await page.fill('#out-width', '64');
  await page.fill('#out-height', '64');
  await page.dispatchEvent('#out-height', 'change');
  await page.check('#dsy-compare');
  const before = Number(await page.getAttribute('body', 'data-gallery-count'));
  await page.click('#run');
  await page.waitForSelector('body[data-synthesis-done="true"]', { timeout: 120_000 });
  assert.equal(Number(await page.getAttribute('body', 'data-gallery-count')), before + 3, 'three results in the gallery');
  assert.match(await page.textContent('#dsy-quality'), /flat/);
  await page.screenshot({ path: `${RESULTS}/design-synthesis.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('stage 3 with step anatomy: E-step and M-step views alternate with the wavelet energy', async () => {
  const { page, errors } = demo;
  await page.click('button[data-stage="synthesis"]');
  await page.uncheck('#dsy-compare');
  await page.selectOption('#dsy-energy-kind', 'haar');
  await page.check('#dsy-anatomy');
  assert.equal(await page.isVisible('#dsy-anatomy-views'), true);
  const halves = [];
  const images = {};
  for (let n = 0; n < 4; n++) {
    const before = await page.textContent('#ds-readout');
    await page.click('#step');
    await page.waitForFunction((b) => document.querySelector('#ds-readout').textContent !== b, before);
    const half = await page.getAttribute('body', 'data-half');
    halves.push(half);
    images[half] = await canvasPixels(page);
  }
  assert.deepEqual(halves.slice(0, 3), ['first-match', 'e-step', 'm-step'], halves.join(' '));
  assert.notDeepEqual(images['e-step'], images['m-step'], 'the E-step and M-step views differ');
  assert.ok(Number(await page.getAttribute('#dsy-weights', 'data-nodes')) > 10, 'the weights are drawn');
  await page.hover('#output-canvas', { position: { x: 30, y: 30 } });
  assert.match(await page.textContent('#dsy-node'), /z_p at exemplar/);
  await page.screenshot({ path: `${RESULTS}/design-anatomy.png`, fullPage: true });
  await page.uncheck('#dsy-anatomy');
  assert.deepEqual(errors, []);
});

test('stage 4: layer-based design runs row by row to done', async () => {
  const { page, errors } = demo;
  await page.click('button[data-stage="layers"]');
  await page.fill('#out-width', '160');
  await page.fill('#out-height', '128');
  await page.dispatchEvent('#out-height', 'change');
  await page.fill('#dl-patch', '24');
  await page.dispatchEvent('#dl-patch', 'change');
  await page.click('#step');
  // The step runs in the page's worker: wait for its reply.
  await page.waitForFunction(() => /row 1\//.test(document.getElementById('ds-readout').textContent));
  await page.click('#run');
  await page.waitForSelector('body[data-layers-done="true"]', { timeout: 60_000 });
  const pixels = await canvasPixels(page);
  for (let i = 3; i < pixels.length; i += 4) assert.equal(pixels[i], 255);
  await page.screenshot({ path: `${RESULTS}/design-layers.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('make tileable shows the 3x3 preview', async () => {
  const { page, errors } = demo;
  await page.click('button[data-stage="tileable"]');
  await page.click('.gallery-item[data-index="0"] button[data-role="base"]');
  await page.click('#dt-make');
  await page.waitForSelector('body[data-tileable="true"]');
  const size = await page.evaluate(() => {
    const c = document.getElementById('output-canvas');
    return [c.width, c.height];
  });
  assert.deepEqual(size, [3 * 54, 3 * 54]);
  await page.screenshot({ path: `${RESULTS}/design-tileable.png`, fullPage: true });
  assert.deepEqual(errors, []);
});
