// The "Flow animation" panel in headless Chromium: frames are made and played, the naive warp is
// drawn beside them, the flow's arrows are drawn, and "Record WebM" produces a video. Then the
// soft-constraint demo: paint on a finished texture optimisation and the synthesis follows.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, finishedOptimizationForPaint, openDemo, openPanel, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

test('the flow panel animates, compares with the naive warp and records a WebM', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'flow', 'grass_64', 96);
  await page.fill('#fl-frames', '10');
  await page.dispatchEvent('#fl-frames', 'change');
  await page.selectOption('#fl-flow', 'whirlpool');
  assert.ok(new Set(await canvasPixels(page, 'fl-arrows')).size > 4, 'the flow is drawn as arrows');

  await page.click('#run');
  await page.waitForSelector('body[data-flow-done="true"]', { timeout: 120_000 });
  assert.equal(await page.getAttribute('body', 'data-flow-frames'), '10');
  assert.match(await page.textContent('#fl-readout'), /frame 10\/10 .* flow energy/);
  const frame = await canvasPixels(page, 'output-canvas');
  const naive = await canvasPixels(page, 'fl-naive');
  assert.equal(naive.length, 96 * 96 * 4);
  assert.notDeepEqual(frame, naive, 'the naive warp differs from the synthesis');
  assert.ok(new Set(await canvasPixels(page, 'fl-playback')).size > 50, 'finished frames play');
  // Frame 1 and the last frame are scored, and the last against frame 1 (the detail metric).
  await page.waitForSelector('#fl-quality-drift[data-flat]', { timeout: 30_000 });
  const scores = await page.$$eval('p.quality[id^="fl-quality"]', (ps) => ps.map((p) => ({ id: p.id, text: p.textContent, ...p.dataset })));
  const [first, last, drift] = scores;
  assert.match(first.text, /^frame 1: quality .* flat \d+\.\d%/);
  assert.match(last.text, /^frame 10: quality .* flat \d+\.\d%/);
  assert.match(drift.text, /^frame 10 against frame 1: flat ×\d+\.\d\d · coherence ×\d+\.\d\d/);
  assert.ok(Math.abs(Number(drift.flat) - Number(last.flat) / Number(first.flat)) < 1e-9, 'the flat ratio is the two frames\'');
  assert.ok(Math.abs(Number(drift.coherence) - Number(last.coherence) / Number(first.coherence)) < 1e-9);
  assert.notEqual(first.coherence, last.coherence, 'two frames were scored, not one twice');

  await page.click('#fl-record');
  await page.waitForSelector('body[data-recorded-bytes]', { timeout: 60_000 });
  const bytes = Number(await page.getAttribute('body', 'data-recorded-bytes'));
  assert.ok(bytes > 1000, `the WebM has ${bytes} bytes`);
  assert.equal(await page.getAttribute('body', 'data-recorded-type'), 'video/webm');
  assert.ok(await page.isVisible('#fl-download'));
  const header = await page.evaluate(async () => {
    const blob = await (await fetch(document.getElementById('fl-download').href)).arrayBuffer();
    return Array.from(new Uint8Array(blob, 0, 4));
  });
  assert.deepEqual(header, [0x1a, 0x45, 0xdf, 0xa3], 'the file starts with the EBML (WebM) signature');
  await page.screenshot({ path: `${RESULTS}/flow.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('a flow drawn by hand: a stroke to the right moves the texture to the right', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'flow', 'tiles_64', 64);
  await page.fill('#fl-frames', '4');
  await page.dispatchEvent('#fl-frames', 'change');
  await page.fill('#fl-strength', '2');
  await page.dispatchEvent('#fl-strength', 'change');
  await page.selectOption('#fl-flow', 'drawn');
  assert.equal(await page.isVisible('#fl-draw-clear'), true);
  assert.match(await page.textContent('#fl-arrows-caption'), /draw strokes here/);
  const box = await page.locator('#fl-arrows').boundingBox();
  await page.mouse.move(box.x + box.width * 0.1, box.y + box.height * 0.5);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.9, box.y + box.height * 0.5, { steps: 10 });
  await page.mouse.up();
  await page.waitForSelector('body[data-flow-strokes="1"]');
  assert.match(await page.textContent('#fl-arrows-caption'), /the drawn flow \(1 stroke\): up to 2\.00 px per frame/);
  await page.screenshot({ path: `${RESULTS}/flow-drawn.png`, fullPage: true });
  while (await page.getAttribute('body', 'data-flow-frames') !== '1') {
    await page.click('#step');
    await page.waitForTimeout(20);
  }
  const first = await canvasPixels(page);
  await page.click('#run');
  await page.waitForSelector('body[data-flow-done="true"]', { timeout: 60_000 });
  const last = await canvasPixels(page);
  // The shift that best carries frame 1 onto frame 4 (3 frames at 2 px): to the right.
  const error = (shift) => {
    let sum = 0;
    for (let y = 8; y < 56; y++) {
      for (let x = 8; x < 56; x++) {
        for (let c = 0; c < 3; c++) sum += (last[(y * 64 + x) * 4 + c] - first[(y * 64 + x - shift) * 4 + c]) ** 2;
      }
    }
    return sum;
  };
  const shifts = [-8, -6, -4, -2, 0, 2, 4, 6, 8];
  const best = shifts.reduce((a, b) => (error(b) < error(a) ? b : a));
  assert.ok(best > 0, `the texture moved by ${best} px (errors ${shifts.map(error).join(', ')})`);
  await page.selectOption('#fl-flow', 'vortex');
  assert.deepEqual(errors, []);
});

test('the sub-pixel box reaches the animation: the same seed makes other frames', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'flow', 'grass_64', 64);
  await page.fill('#fl-frames', '3');
  await page.dispatchEvent('#fl-frames', 'change');
  const lastFrame = async (subPixel) => {
    await page.setChecked('#fl-subpixel', subPixel);
    await page.dispatchEvent('#fl-subpixel', 'change');
    await page.evaluate(() => { delete document.body.dataset.flowDone; });
    await page.click('#run');
    await page.waitForSelector('body[data-flow-done="true"]', { timeout: 120_000 });
    assert.equal(await page.getAttribute('body', 'data-flow-frames'), '3');
    return canvasPixels(page, 'output-canvas');
  };
  const whole = await lastFrame(false);
  const sub = await lastFrame(true);
  assert.equal(sub.length, 64 * 64 * 4);
  assert.notDeepEqual(sub, whole, 'sub-pixel matches change the frames');
  assert.deepEqual(errors, []);
});

test('painting on a finished texture optimisation pulls it toward the paint', async () => {
  const { page, errors } = demo;
  const redness = await finishedOptimizationForPaint(page);
  const before = await redness();
  await page.check('#to-paint');
  await page.fill('#to-colour', '#ff0000');
  const box = await page.locator('#output-canvas').boundingBox();
  const at = (fx, fy) => [box.x + fx * box.width, box.y + fy * box.height];
  await page.mouse.move(...at(0.15, 0.5));
  await page.mouse.down();
  for (let fx = 0.15; fx <= 0.85; fx += 0.02) await page.mouse.move(...at(fx, 0.5));
  for (let fx = 0.85; fx >= 0.15; fx -= 0.02) await page.mouse.move(...at(fx, 0.46));
  for (let fx = 0.15; fx <= 0.85; fx += 0.02) await page.mouse.move(...at(fx, 0.54));
  await page.mouse.up();
  await page.waitForSelector('body[data-constraints-set="1"]');
  await page.waitForFunction(() => document.getElementById('status').textContent === 'done', null, { timeout: 60_000 });
  const after = await redness();
  assert.ok(after > before + 30, `red minus green in the painted band: ${before.toFixed(1)} -> ${after.toFixed(1)}`);
  assert.match(await page.textContent('#to-readout'), /constraint error/);
  await page.screenshot({ path: `${RESULTS}/constraints.png`, fullPage: true });
  assert.deepEqual(errors, []);
});
