// The "Fill and extend" panel in headless Chromium: a hole painted with the mouse and with the
// keyboard brush is filled (the output differs from the input inside the hole and equals it
// byte for byte outside), the fill's patches view toggles, an empty hole is refused with the
// package's message, and uncrop gives an output larger than the input by its border.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, openDemo, openPanel, RESULTS, tabTo } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

/** Two animation frames: the panel redraws the painted hole once per frame. */
const frames = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

const holePixels = async (page) => Number(await page.getAttribute('body', 'data-hole-pixels'));

const canvasSize = (page) => page.evaluate(() => {
  const c = document.getElementById('output-canvas');
  return [c.width, c.height];
});

test('a hole painted with the mouse and the keyboard is filled, and nothing outside it changes', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'inpainting', 'tiles_128');
  assert.equal(await page.isDisabled('#out-width'), true, 'the output is the image itself');
  const input = await canvasPixels(page, 'exemplar-canvas');
  assert.deepEqual(await canvasSize(page), [128, 128]);
  assert.deepEqual(await canvasPixels(page), input, 'before painting, the image is shown as it is');

  // The mouse: a diagonal stroke in the upper left quarter.
  await page.fill('#ip-size', '5');
  const box = await page.locator('#output-canvas').boundingBox();
  await page.mouse.move(box.x + box.width * 0.25, box.y + box.height * 0.25);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.45, box.y + box.height * 0.4, { steps: 10 });
  await page.mouse.up();
  const byMouse = await holePixels(page);
  assert.ok(byMouse > 150, `the mouse stroke marked ${byMouse} pixels`);

  // The keyboard: Tab to the canvas, move the brush cursor, hold Space and draw a stroke down.
  await page.focus('#ip-size');
  await tabTo(page, '#output-canvas');
  assert.match(await page.getAttribute('#output-canvas', 'aria-description'), /hold Space to paint/);
  for (let n = 0; n < 10; n++) await page.keyboard.press('ArrowRight');
  for (let n = 0; n < 5; n++) await page.keyboard.press('ArrowDown');
  assert.equal(await page.getAttribute('#output-canvas', 'data-brush'), '0.70,0.60');
  await page.keyboard.down(' ');
  for (let n = 0; n < 10; n++) await page.keyboard.press('ArrowDown');
  assert.equal(await page.isVisible('.brush-ring.painting'), true, 'the cursor shows the stroke');
  await page.keyboard.up(' ');
  const byBoth = await holePixels(page);
  assert.ok(byBoth > byMouse + 100, `the keyboard stroke added ${byBoth - byMouse} pixels`);

  // The preview tints the hole: the pixels that differ from the input are the hole.
  await frames(page);
  const preview = await canvasPixels(page);
  const hole = new Uint8Array(128 * 128);
  for (let i = 0; i < hole.length; i++) {
    for (let c = 0; c < 3; c++) if (preview[i * 4 + c] !== input[i * 4 + c]) hole[i] = 1;
  }
  assert.equal(hole.reduce((a, b) => a + b, 0), byBoth, 'the tinted pixels are the painted ones');
  const at = (fx, fy) => hole[Math.floor(fy * 128) * 128 + Math.floor(fx * 128)];
  assert.equal(at(0.35, 0.32), 1, 'the mouse stroke is in the hole');
  assert.equal(at(0.7, 0.7), 1, 'the keyboard stroke is in the hole');
  assert.equal(at(0.9, 0.1), 0, 'a corner nobody painted is not');
  assert.match(await page.textContent('#ip-readout'), new RegExp(`hole: ${byBoth} pixels`));

  // Two steps of the fill, and its patches view: known pixels grey, the patches in colours.
  for (const n of [1, 2]) {
    await page.click('#step');
    await page.waitForSelector(`body[data-inpainting-patches="${n}"]`);
  }
  assert.equal(await page.getAttribute('body', 'data-inpainting-stage'), 'fill');
  assert.match(await page.textContent('#ip-readout'), /^fill · patch at \(\d+, \d+\) .* \/ \d+ hole pixels filled .* · 2 patches/);
  await page.check('#ip-patches');
  const patches = await canvasPixels(page);
  const isGrey = (i) => patches[i] === 128 && patches[i + 1] === 128 && patches[i + 2] === 128;
  assert.ok(isGrey((120 * 128 + 120) * 4), 'a known pixel is grey in the patches view');
  let coloured = 0;
  for (let i = 0; i < hole.length; i++) if (hole[i] && patches[i * 4 + 3] === 255 && !isGrey(i * 4)) coloured++;
  assert.ok(coloured > 50, `${coloured} hole pixels show the colour of their patch`);
  await page.screenshot({ path: `${RESULTS}/inpainting-fill-patches.png`, fullPage: true });
  await page.uncheck('#ip-patches');

  // Run to done: the optimisation's energy is plotted, the readout says all is filled.
  await page.click('#run');
  await page.waitForSelector('body[data-inpainting-done="true"]', { timeout: 60_000 });
  assert.equal(await page.textContent('#status'), 'done');
  assert.match(await page.textContent('#ip-readout'), new RegExp(`^done · level .* energy .* ${byBoth} / ${byBoth} hole pixels filled \\(100%\\)`));
  const plotted = await canvasPixels(page, 'ip-energy');
  let orange = 0;
  for (let i = 0; i < plotted.length; i += 4) if (plotted[i] > 200 && plotted[i + 1] > 140 && plotted[i + 1] < 190 && plotted[i + 2] < 120) orange++;
  assert.ok(orange > 30, 'the energy plot has its line');

  const output = await canvasPixels(page);
  assert.equal(output.length, input.length);
  let outsideChanged = 0;
  let insideChanged = 0;
  let insideDifference = 0;
  for (let i = 0; i < hole.length; i++) {
    const d = [0, 1, 2, 3].reduce((sum, c) => sum + Math.abs(output[i * 4 + c] - input[i * 4 + c]), 0);
    if (hole[i]) {
      insideDifference += d;
      if (d > 0) insideChanged++;
    } else if (d > 0) outsideChanged++;
  }
  assert.equal(outsideChanged, 0, 'every pixel outside the hole is the input\'s');
  assert.ok(insideChanged > 0.5 * byBoth, `${insideChanged} of ${byBoth} hole pixels changed`);
  assert.ok(insideDifference / byBoth > 10, `mean difference in the hole ${(insideDifference / byBoth).toFixed(1)}`);
  assert.equal(await page.isDisabled('#ip-download'), false, 'the result can be downloaded');
  await page.screenshot({ path: `${RESULTS}/inpainting-fill.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('running with an empty hole shows the package\'s error, and painting starts over', async () => {
  const { page, errors } = demo;
  await page.click('#ip-clear');
  assert.equal(await holePixels(page), 0);
  await page.click('#run');
  await page.waitForSelector('#error:not([hidden])');
  assert.match(await page.textContent('#error'), /mask.*empty.*no pixel is marked to fill/);
  assert.equal(await page.textContent('#status'), 'stopped');
  // Enter paints one dab with the keyboard; Run then fills it and the error goes.
  await page.focus('#output-canvas');
  await page.keyboard.press('Enter');
  assert.ok((await holePixels(page)) > 20);
  await page.click('#run');
  await page.waitForSelector('body[data-inpainting-done="true"]', { timeout: 60_000 });
  assert.equal(await page.isHidden('#error'), true);
  assert.deepEqual(errors, []);
});

test('uncrop: the output is the input inside its new border, filled', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'inpainting', 'brick_64');
  const input = await canvasPixels(page, 'exemplar-canvas');
  await page.check('input[name="ip-mode"][value="uncrop"]');
  assert.equal(await page.isHidden('#ip-brush-tools'), true, 'no brush in uncrop mode');
  assert.equal(await page.getAttribute('#output-canvas', 'data-paint'), null, 'the canvas is not paintable');
  // One number for all sides, then per side.
  await page.fill('#ip-border', '16');
  await page.dispatchEvent('#ip-border', 'change');
  assert.deepEqual(await canvasSize(page), [96, 96]);
  const border = { top: 8, right: 16, bottom: 24, left: 12 };
  for (const [side, width] of Object.entries(border)) {
    await page.fill(`#ip-${side}`, String(width));
    await page.dispatchEvent(`#ip-${side}`, 'change');
  }
  const [width, height] = [64 + border.left + border.right, 64 + border.top + border.bottom];
  assert.deepEqual(await canvasSize(page), [width, height]);
  assert.match(await page.textContent('#ip-readout'), new RegExp(`64×64 → ${width}×${height}`));
  assert.equal(await holePixels(page), width * height - 64 * 64);

  await page.click('#run');
  await page.waitForSelector('body[data-inpainting-done="true"]', { timeout: 60_000 });
  assert.deepEqual(await canvasSize(page), [width, height], 'the output is larger than the input by the border');
  const output = await canvasPixels(page);
  let insideChanged = 0;
  const borderColours = new Set();
  let dark = 0;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const o = (y * width + x) * 4;
      const [ix, iy] = [x - border.left, y - border.top];
      if (ix >= 0 && iy >= 0 && ix < 64 && iy < 64) {
        const i = (iy * 64 + ix) * 4;
        for (let c = 0; c < 4; c++) if (output[o + c] !== input[i + c]) insideChanged++;
      } else {
        borderColours.add(`${output[o]},${output[o + 1]},${output[o + 2]}`);
        if (output[o] + output[o + 1] + output[o + 2] < 30) dark++;
      }
    }
  }
  assert.equal(insideChanged, 0, 'the input is inside its border unchanged');
  const inputColours = new Set();
  for (let i = 0; i < input.length; i += 4) inputColours.add(`${input[i]},${input[i + 1]},${input[i + 2]}`);
  assert.ok(borderColours.size > inputColours.size / 2, `the border is texture (${borderColours.size} colours; the input has ${inputColours.size})`);
  assert.ok(dark < 0.02 * (width * height - 64 * 64), `${dark} border pixels are left near black`);
  assert.match(await page.textContent('#ip-readout'), /^done · .* \(100%\)/);
  await page.screenshot({ path: `${RESULTS}/inpainting-uncrop.png`, fullPage: true });
  assert.deepEqual(errors, []);
});
