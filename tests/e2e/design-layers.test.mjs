// The "Layers" stage of the texture-design panel (Shen et al. 2009, section 3.4) in headless
// Chromium with a painted layout: four layers of the sample (as it is, turned by 30 degrees, at
// scale 2 and at scale 0.5), three regions painted with the pointer and one with the keyboard
// brush over the preview, the design run to done with all four layers and the painted layout;
// then painting starts the design over, a removed layer takes its paint with it, and Clear gives
// every pixel back to layer 1.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, openDemo, openPanel, RESULTS, tabTo } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

const [W, H] = [160, 128];

/** The numbers of a comma-separated data- attribute of the body. */
const bodyFigures = async (page, name) => (await page.getAttribute('body', `data-${name}`)).split(',').map(Number);

/** Sets a number input as typing and leaving it would. */
async function setNumber(page, selector, value) {
  await page.fill(selector, String(value));
  await page.dispatchEvent(selector, 'change');
}

const rowCount = (page) => page.$$eval('#dl-rows [data-layer]', (rows) => rows.length);

/** A pointer stroke over the output from output pixel `from` to `to`. */
async function stroke(page, from, to) {
  await page.locator('#output-canvas').scrollIntoViewIfNeeded();
  const box = await page.locator('#output-canvas').boundingBox();
  const at = ([x, y]) => [box.x + ((x + 0.5) / W) * box.width, box.y + ((y + 0.5) / H) * box.height];
  await page.mouse.move(...at(from));
  await page.mouse.down();
  await page.mouse.move(...at(to), { steps: 12 });
  await page.mouse.up();
}

test('four layers with their own deformations, a painted layout, run to done', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'design', 'potatoes_64', [W, H]);
  await page.waitForSelector('body[data-gallery-count="1"]');
  await page.click('button[data-stage="layers"]');
  await page.waitForSelector('body[data-design-stage="layers"]');
  await setNumber(page, '#dl-patch', 24);
  // Layer 1 the base, layer 2 the reference: the list the stage opens with.
  assert.equal(await rowCount(page), 2);
  assert.equal(await page.isVisible('[data-layer="0"] .dl-remove'), false, 'layer 1 cannot be removed');
  assert.deepEqual(await page.$$eval('#dl-rows .dl-source', (s) => s.map((x) => x.value)), ['base', 'reference']);
  await setNumber(page, '[data-layer="1"] .dl-rotate', 30);
  await page.click('#dl-add');
  await setNumber(page, '[data-layer="2"] .dl-scale', 2);
  await page.click('#dl-add');
  await setNumber(page, '[data-layer="3"] .dl-scale', 0.5);
  assert.equal(await rowCount(page), 4);
  assert.deepEqual(await page.$$eval('#dl-rows .dl-source', (s) => s.map((x) => x.value)), ['base', 'reference', 'base', 'base']);

  await page.selectOption('#dl-layout', 'painted');
  assert.equal(await page.isVisible('#dl-paint-tools'), true, 'the brush shows in "painted"');
  await page.waitForFunction((n) => document.body.dataset.layersPainted === `${n},0,0,0`, W * H);
  assert.deepEqual(await page.$eval('#output-canvas', (c) => [c.width, c.height]), [W, H], 'the preview is at the output size');

  // Three regions with the pointer: layer 2 along the top, layer 3 along the bottom, layer 4
  // down the right.
  await page.check('input[name="dl-brush"][value="2"]');
  await stroke(page, [12, 16], [148, 16]);
  await page.check('input[name="dl-brush"][value="3"]');
  await stroke(page, [12, 112], [148, 112]);
  await page.check('input[name="dl-brush"][value="4"]');
  await stroke(page, [146, 34], [146, 94]);
  const byPointer = await bodyFigures(page, 'layers-painted');
  assert.equal(byPointer.length, 4);
  for (const k of [1, 2, 3]) assert.ok(byPointer[k] > 1000, `${byPointer[k]} pixels painted for layer ${k + 1}`);

  // One region with the keyboard: the brush of layer 3, then from the canvas's middle leftwards
  // with Space held.
  await page.focus('input[name="dl-brush"][value="3"]');
  await page.keyboard.press('Space');
  assert.equal(await page.isChecked('input[name="dl-brush"][value="3"]'), true);
  await tabTo(page, '#output-canvas');
  assert.match(await page.getAttribute('#output-canvas', 'aria-description'), /Paint which layer each pixel takes: .*hold Space to paint/);
  await page.keyboard.down(' ');
  for (let n = 0; n < 12; n++) await page.keyboard.press('ArrowLeft');
  await page.keyboard.up(' ');
  const painted = await bodyFigures(page, 'layers-painted');
  assert.ok(painted[2] > byPointer[2] + 500, `the keyboard painted ${painted[2] - byPointer[2]} pixels for layer 3`);
  assert.equal(painted.reduce((a, b) => a + b, 0), W * H);
  assert.match(await page.textContent('#dl-about'), /^4 layers \(1: sample I; 2: sample I, rotated 30°; 3: sample I, scaled ×2; 4: sample I, scaled ×0\.5\)\. Layout: painted over the output/);
  // The preview: each layer's colour over the output, blue (layer 1) at the left edge's middle,
  // orange (layer 2) along the top.
  const preview = await canvasPixels(page);
  const pixel = (pixels, x, y) => pixels.slice((y * W + x) * 4, (y * W + x) * 4 + 4);
  const [r1, , b1] = pixel(preview, 12, 64);
  const [r2, , b2] = pixel(preview, 80, 16);
  assert.ok(b1 > r1, `layer 1's pixel is bluish: ${pixel(preview, 12, 64)}`);
  assert.ok(r2 > b2, `layer 2's pixel is orange: ${pixel(preview, 80, 16)}`);
  await page.locator('#output-canvas').scrollIntoViewIfNeeded();
  await page.screenshot({ path: `${RESULTS}/design-layers-painted.png`, fullPage: true });

  const gallery = Number(await page.getAttribute('body', 'data-gallery-count'));
  await page.click('#run');
  await page.waitForSelector('body[data-layers-done="true"]', { timeout: 120_000 });
  assert.equal(await page.isHidden('#error'), true, 'the design took every layer');
  // The run used the four layers and the painted layout as painted.
  assert.equal(Number(await page.getAttribute('body', 'data-layers-count')), 4);
  assert.deepEqual(await bodyFigures(page, 'layers-layout'), painted);
  assert.match(await page.textContent('#ds-readout'), /^4 layers · painted layout · row \d+\/\d+ /);
  assert.equal(Number(await page.getAttribute('body', 'data-gallery-count')), gallery + 1, 'the design joined the gallery');
  // The output is drawn: opaque everywhere, and not one flat colour.
  assert.deepEqual(await page.$eval('#output-canvas', (c) => [c.width, c.height]), [W, H]);
  const pixels = await canvasPixels(page);
  const colours = new Set();
  for (let i = 0; i < pixels.length; i += 4) {
    assert.equal(pixels[i + 3], 255);
    colours.add((pixels[i] << 16) | (pixels[i + 1] << 8) | pixels[i + 2]);
  }
  assert.ok(colours.size > 200, `${colours.size} colours in the output`);
  assert.notDeepEqual(pixels, preview, 'the design replaced the preview');
  await page.locator('#output-canvas').scrollIntoViewIfNeeded();
  await page.screenshot({ path: `${RESULTS}/design-layers-result.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('painting starts the design over; remove and Clear take the paint with them', async () => {
  const { page, errors } = demo;
  // A dab for layer 4 after the run: the finished design is dropped and the preview is back.
  await page.check('input[name="dl-brush"][value="4"]');
  await stroke(page, [40, 60], [44, 60]);
  assert.equal(await page.getAttribute('body', 'data-layers-done'), null);
  assert.equal(await page.getAttribute('body', 'data-layers-count'), null);
  const painted = await bodyFigures(page, 'layers-painted');

  // Removing layer 3: layer 4's row and paint move up, layer 3's paint goes to layer 1.
  await page.click('[data-layer="2"] .dl-remove');
  assert.equal(await rowCount(page), 3);
  assert.equal(await page.inputValue('[data-layer="2"] .dl-scale'), '0.5');
  assert.equal(await page.isChecked('input[name="dl-brush"][value="3"]'), true, 'the brush follows its layer');
  assert.deepEqual(await bodyFigures(page, 'layers-painted'), [painted[0] + painted[2], painted[1], painted[3]]);
  assert.match(await page.textContent('#dl-about'), /^3 layers /);

  // At most six layers.
  for (let n = 3; n < 6; n++) await page.click('#dl-add');
  assert.equal(await rowCount(page), 6);
  assert.equal(await page.isDisabled('#dl-add'), true, '"Add layer" is greyed at six');

  await page.click('#dl-clear');
  assert.deepEqual(await bodyFigures(page, 'layers-painted'), [W * H, 0, 0, 0, 0, 0]);
  assert.deepEqual(errors, []);
});
