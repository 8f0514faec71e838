// The "Graphcut textures" and "Graph-cut merge" panels in headless Chromium: placements are drawn,
// the run reaches done, the seam overlay toggles, and a merge with painted constraints completes.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, openDemo, openPanel, qualityInPage, RESULTS } from './harness.mjs';

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

test('the graph-cut panel places patches live and runs to done', async () => {
  const { page, errors } = demo;
  await page.click('button[data-panel="graphcut"]');
  await page.click('button[data-sample="tiles_64"]');
  await page.waitForSelector('body[data-exemplar="tiles 64×64"]');
  await page.fill('#out-width', '160');
  await page.fill('#out-height', '128');
  await page.dispatchEvent('#out-height', 'change');
  await page.fill('#gc-refine', '6');
  await page.dispatchEvent('#gc-refine', 'change');
  await page.click('#step');
  await page.waitForSelector('body[data-patches="1"]');
  const first = await canvasPixels(page);
  await page.click('#step');
  await page.waitForSelector('body[data-patches="2"]');
  assert.notDeepEqual(first, await canvasPixels(page), 'the second patch changes the canvas');
  await page.click('#run');
  await page.waitForSelector('body[data-graphcut-done="true"]', { timeout: 60_000 });
  assert.match(await page.textContent('#gc-readout'), /patches · .* · covered/);
  const withSeams = await canvasPixels(page);
  assert.ok(redPixels(withSeams) > 50, 'the seam overlay is drawn');
  assert.match(await page.textContent('#gc-quality'), /coherence .* completeness .* histogram/);
  // Graph cut copies exemplar pixels: its coherence (about 0.00026 here) is far below noise's
  // (0.08) and below a flat image's (0.001, itself low: a flat patch is close to smooth ones).
  const coherence = Number(await page.getAttribute('#gc-quality', 'data-coherence'));
  const noise = await qualityInPage(page, 'tiles_64', 'noise', 160, 128);
  const flat = await qualityInPage(page, 'tiles_64', 'flat', 160, 128);
  assert.ok(coherence < noise.coherence / 10, `coherence ${coherence}, noise ${noise.coherence}`);
  assert.ok(coherence < flat.coherence / 2, `coherence ${coherence}, flat ${flat.coherence}`);
  await page.screenshot({ path: `${RESULTS}/graphcut.png`, fullPage: true });
  await page.uncheck('#gc-seams');
  assert.equal(redPixels(await canvasPixels(page)), 0, 'the seam overlay toggles off');
  await page.check('#gc-labels');
  await page.screenshot({ path: `${RESULTS}/graphcut-labels.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('sub-patch matching covers the output patch by patch and runs to done', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'graphcut', 'stone_64', [160, 96]);
  await page.selectOption('#gc-placement', 'sub-patch');
  await page.dispatchEvent('#gc-placement', 'change');
  await page.fill('#gc-refine', '4');
  await page.dispatchEvent('#gc-refine', 'change');
  await page.click('#step');
  await page.waitForSelector('body[data-patches="1"]');
  await page.click('#step');
  await page.waitForSelector('body[data-patches="2"]');
  assert.match(await page.textContent('#gc-readout'), /2 patches · .* · covering/);
  await page.click('#run');
  await page.waitForSelector('body[data-graphcut-done="true"]', { timeout: 60_000 });
  assert.match(await page.textContent('#gc-readout'), /patches · .* · covered/);
  assert.ok(Number(await page.getAttribute('body', 'data-patches')) > 4, 'covering took several patches');
  assert.match(await page.textContent('#gc-quality'), /coherence .* completeness .* histogram/);
  const pixels = await canvasPixels(page);
  assert.ok(new Set(pixels).size > 50, 'the output is a texture, not a flat colour');
  await page.screenshot({ path: `${RESULTS}/graphcut-sub-patch.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('patches from scaled exemplars, smaller towards the top, run to done', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'graphcut', 'brick_64', [160, 128]);
  await page.fill('#gc-refine', '2');
  await page.dispatchEvent('#gc-refine', 'change');
  await page.fill('#gc-scales', '0.5, 1.5');
  await page.dispatchEvent('#gc-scales', 'change');
  await page.check('#gc-perspective');
  await page.click('#run');
  await page.waitForSelector('body[data-graphcut-done="true"]', { timeout: 60_000 });
  assert.match(await page.textContent('#gc-readout'), /patches · .* · covered/);
  await page.screenshot({ path: `${RESULTS}/graphcut-scales.png`, fullPage: true });
  // Back to the defaults for the tests that follow.
  await page.fill('#gc-scales', '');
  await page.dispatchEvent('#gc-scales', 'change');
  await page.uncheck('#gc-perspective');
  assert.deepEqual(errors, []);
});

test('an output wider than 512 is scored on its central 512 columns, and the readout says so', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'graphcut', 'gravel_64', [640, 96]);
  await page.fill('#gc-refine', '0');
  await page.dispatchEvent('#gc-refine', 'change');
  await page.click('#run');
  await page.waitForSelector('body[data-graphcut-done="true"]', { timeout: 60_000 });
  assert.match(await page.textContent('#gc-quality'), /^quality \(of the central 512×96 of 640×96\) .*coherence/);
  assert.equal(await page.getAttribute('#gc-quality', 'data-window'), '64,0,512,96');
  await page.screenshot({ path: `${RESULTS}/graphcut-quality-window.png`, fullPage: true });
  // The same figures as the window cut out of the canvas (without the seam overlay) and scored directly.
  await page.uncheck('#gc-seams');
  const pixels = await canvasPixels(page);
  await page.check('#gc-seams');
  const cut = [];
  for (let y = 0; y < 96; y++) cut.push(...pixels.slice((y * 640 + 64) * 4, (y * 640 + 576) * 4));
  const direct = await qualityInPage(page, 'gravel_64', cut, 512, 96);
  assert.equal(Number(await page.getAttribute('#gc-quality', 'data-coherence')), direct.coherence);
  assert.equal(Number(await page.getAttribute('#gc-quality', 'data-completeness')), direct.completeness);
  assert.deepEqual(errors, []);
});

test('a merge with painted constraints completes and shows its seam', async () => {
  const { page, errors } = demo;
  await page.click('button[data-panel="merge"]');
  await page.click('button[data-sample="tiles_128"]');
  await page.waitForSelector('body[data-exemplar="tiles 128×128"]');
  const box = await page.locator('#output-canvas').boundingBox();
  // Paint a vertical stroke for the first image, then one for the second.
  const stroke = async (fraction) => {
    await page.mouse.move(box.x + box.width * fraction, box.y + 5);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width * fraction, box.y + box.height - 5, { steps: 12 });
    await page.mouse.up();
  };
  await page.check('input[name="mg-brush"][value="1"]');
  await stroke(0.45);
  // Paint for the first image beyond its right edge: the brush leaves it unpainted, so the
  // merge (which refuses paint a source does not cover) still runs.
  await stroke(0.9);
  await page.check('input[name="mg-brush"][value="2"]');
  await stroke(0.75);
  await page.click('#run');
  await page.waitForSelector('body[data-merge-done="true"]', { timeout: 30_000 });
  assert.match(await page.textContent('#mg-readout'), /merged · cut cost/);
  assert.ok(redPixels(await canvasPixels(page)) > 20, 'the seam is drawn');
  await page.screenshot({ path: `${RESULTS}/merge.png`, fullPage: true });
  // The merge's canvas is the two images side by side and it draws nothing at random: the
  // toolbar's size and seed are greyed with the reason, and live again on the next panel.
  for (const id of ['out-width', 'out-height', 'seed']) {
    assert.equal(await page.isDisabled(`#${id}`), true, `#${id} disabled under merge`);
  }
  assert.match(await page.getAttribute('#out-width', 'title'), /side by side/);
  assert.match(await page.getAttribute('#seed', 'title'), /nothing at random/);
  await page.click('button[data-panel="graphcut"]');
  for (const id of ['out-width', 'out-height', 'seed']) {
    assert.equal(await page.isDisabled(`#${id}`), false, `#${id} live again under graph cut`);
    assert.equal(await page.getAttribute(`#${id}`, 'title'), null);
  }
  assert.deepEqual(errors, []);
});
