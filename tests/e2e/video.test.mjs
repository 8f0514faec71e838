// The "Video textures" panel in headless Chromium: the demo clip (a film strip PNG) is decoded in
// the page, a loop is synthesised in the worker one patch at a time, the x-t slice and the loop
// point are drawn, the loop plays, and "Record WebM" produces a video.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, openDemo, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

test('the demo clip loops, with its x-t slice, loop point, playback and WebM', async () => {
  const { page, errors } = demo;
  await page.click('button[data-panel="video"]');
  // The video's size comes from its own field: the toolbar's output size is greyed, saying so;
  // the seed stays live (random placement and offsets draw from it).
  assert.equal(await page.isDisabled('#out-width'), true);
  assert.equal(await page.isDisabled('#out-height'), true);
  assert.match(await page.getAttribute('#out-height', 'title'), /own size field/);
  assert.equal(await page.isDisabled('#seed'), false);
  await page.fill('#vt-size', '48');
  await page.dispatchEvent('#vt-size', 'change');
  await page.fill('#vt-frames', '36');
  await page.dispatchEvent('#vt-frames', 'change');
  await page.waitForFunction(() => /input clip: 48×48, 36 frames/.test(document.getElementById('vt-input-caption').textContent));

  // k of 7.D is off in loop mode (the loop closes through 7.A's transition), on in the others.
  assert.equal(await page.isDisabled('#vt-fixed'), true);
  assert.match(await page.getAttribute('#vt-fixed-label', 'title'), /Off: a loop \(7\.A\)/);
  assert.equal(await page.isDisabled('#vt-window'), false);
  assert.equal(await page.isDisabled('#vt-scale'), true);
  await page.selectOption('#vt-mode', 'offsets');
  assert.equal(await page.isDisabled('#vt-fixed'), false);
  assert.equal(await page.isDisabled('#vt-window'), true);
  await page.selectOption('#vt-mode', 'loop');

  await page.click('#step');
  await page.waitForSelector('body[data-video-patches="1"]', { timeout: 60_000 });
  assert.match(await page.textContent('#vt-readout'), /patch 1 at \(x -?\d+, y -?\d+, t -?\d+\) .* voxels taken .* cut cost/);

  await page.click('#run');
  await page.waitForSelector('body[data-video-done="true"]', { timeout: 120_000 });
  const frames = Number(await page.getAttribute('body', 'data-video-frames'));
  assert.ok(frames >= 2, `${frames} output frames`);
  // The frame shown is the one of the seam window that the seam surface crosses most.
  const seamPixels = Number(await page.getAttribute('body', 'data-video-seam-pixels'));
  assert.ok(seamPixels > 0, `the frame shown (${await page.getAttribute('body', 'data-video-shown-frame')}) has ${seamPixels} seam pixels`);
  const slice = await canvasPixels(page, 'vt-slice');
  assert.equal(slice.length, 48 * frames * 4, 'the x-t slice is width x frames');
  assert.ok(new Set(slice).size > 20, 'the x-t slice is drawn');
  assert.ok(new Set(await canvasPixels(page, 'vt-loop-last')).size > 20, 'the loop point is drawn');
  // 7.A: the loop closes at the centre of the seam window, where the cut joins the clip to its
  // shifted copy; the caption names the frames on either side.
  const [, before, after] = (await page.textContent('#vt-loop-caption')).match(/frame (\d+) is followed by frame (\d+)/);
  assert.equal(Number(after), (Number(before) % frames) + 1);
  await page.waitForFunction(() => Number(document.body.dataset.videoPlayed ?? 0) > 3);
  assert.ok(new Set(await canvasPixels(page, 'vt-playback')).size > 20, 'the loop plays');
  // The cross-fade baseline plays beside it, as long as the output.
  assert.equal(await page.getAttribute('body', 'data-video-baseline-frames'), String(frames));
  assert.match(await page.textContent('#vt-crossfade-caption'), /cross-fade loop \(baseline\): \d+ frames, the first \d+ blended/);
  assert.ok(new Set(await canvasPixels(page, 'vt-crossfade')).size > 20, 'the baseline plays');

  await page.click('#vt-record');
  await page.waitForSelector('body[data-recorded-bytes]', { timeout: 60_000 });
  const bytes = Number(await page.getAttribute('body', 'data-recorded-bytes'));
  assert.ok(bytes > 1000, `the WebM has ${bytes} bytes`);
  const header = await page.evaluate(async () => {
    const blob = await (await fetch(document.getElementById('vt-download').href)).arrayBuffer();
    return Array.from(new Uint8Array(blob, 0, 4));
  });
  assert.deepEqual(header, [0x1a, 0x45, 0xdf, 0xa3], 'the file starts with the EBML (WebM) signature');
  await page.screenshot({ path: `${RESULTS}/video.png`, fullPage: true });

  // The recorded WebM, dropped back in as a video file: decoded frame by frame through a <video>
  // element, then looped in its turn.
  const webm = await page.evaluate(async () => {
    const blob = await (await fetch(document.getElementById('vt-download').href)).arrayBuffer();
    return Array.from(new Uint8Array(blob));
  });
  await page.setInputFiles('#vt-file', { name: 'loop.webm', mimeType: 'video/webm', buffer: Buffer.from(webm) });
  await page.fill('#vt-size', '32');
  await page.dispatchEvent('#vt-size', 'change');
  await page.fill('#vt-frames', '24');
  await page.dispatchEvent('#vt-frames', 'change');
  await page.waitForFunction(() => /input clip: 32×32, \d+ frames/.test(document.getElementById('vt-input-caption').textContent), null, { timeout: 60_000 });
  const decoded = Number((await page.textContent('#vt-input-caption')).match(/(\d+) frames/)[1]);
  assert.ok(decoded >= 8, `${decoded} frames decoded from the WebM`);
  await page.click('#run');
  await page.waitForSelector('body[data-video-done="true"]', { timeout: 120_000 });
  assert.ok(Number(await page.getAttribute('body', 'data-video-frames')) >= 2);
  await page.screenshot({ path: `${RESULTS}/video-file.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('a spatial extension at 1.5 times the clip, with the gradient cost and its own refinements', async () => {
  const { page, errors } = demo;
  await page.selectOption('#vt-source', 'water');
  await page.fill('#vt-size', '32');
  await page.dispatchEvent('#vt-size', 'change');
  await page.fill('#vt-frames', '12');
  await page.dispatchEvent('#vt-frames', 'change');
  await page.selectOption('#vt-mode', 'extend');
  assert.equal(await page.isDisabled('#vt-scale'), false);
  await page.selectOption('#vt-scale', '1.5');
  await page.fill('#vt-out-frames', '8');
  await page.dispatchEvent('#vt-out-frames', 'change');
  await page.fill('#vt-fixed', '2');
  await page.dispatchEvent('#vt-fixed', 'change');
  await page.fill('#vt-refine', '1');
  await page.dispatchEvent('#vt-refine', 'change');
  await page.check('#vt-gradient');
  await page.click('#run');
  await page.waitForSelector('body[data-video-done="true"]', { timeout: 120_000 });
  assert.equal(await page.$eval('#output-canvas', (c) => `${c.width}x${c.height}`), '48x48');
  assert.equal(await page.getAttribute('body', 'data-video-frames'), '8');
  await page.screenshot({ path: `${RESULTS}/video-extend.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('the ripples clip loops, feathered, with a seam surface that cuts at different times across the frame', async () => {
  const { page, errors } = demo;
  await page.selectOption('#vt-source', 'ripples');
  await page.fill('#vt-size', '64');
  await page.dispatchEvent('#vt-size', 'change');
  await page.fill('#vt-frames', '60');
  await page.dispatchEvent('#vt-frames', 'change');
  await page.selectOption('#vt-mode', 'loop');
  await page.selectOption('#vt-blend', 'feather');
  await page.waitForFunction(() => /input clip: 64×64, 60 frames/.test(document.getElementById('vt-input-caption').textContent));
  await page.click('#run');
  await page.waitForSelector('body[data-video-done="true"]', { timeout: 120_000 });
  // A cut at one time for every pixel would leave no seam inside any frame; the frame shown is
  // the one the seam surface crosses most.
  const seamPixels = Number(await page.getAttribute('body', 'data-video-seam-pixels'));
  assert.ok(seamPixels >= 64, `the frame shown has ${seamPixels} seam pixels`);
  // Three good transitions were seamed; the readout names the one kept.
  assert.match(await page.textContent('#vt-readout'), /kept transition [123] of 3 \(loop of \d+ frames\)/);
  await page.screenshot({ path: `${RESULTS}/video-ripples.png`, fullPage: true });
  assert.deepEqual(errors, []);
});
