// The "Feature-guided" panel in headless Chromium: the exemplar's feature map is drawn and can be
// edited, the synthesis places patches with the teaching overlay, and the plain graph cut runs
// beside it with both broken-feature counts shown.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, openDemo, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

test('feature-guided synthesis runs beside plain graph cut with both broken-feature counts', async () => {
  const { page, errors } = demo;
  await page.click('button[data-panel="features"]');
  await page.click('button[data-sample="tiles_64"]');
  await page.waitForSelector('body[data-exemplar="tiles 64×64"]');
  await page.fill('#out-width', '128');
  await page.fill('#out-height', '128');
  await page.dispatchEvent('#out-height', 'change');
  await page.fill('#fg-patch', '32');
  await page.dispatchEvent('#fg-patch', 'change');
  const caption = await page.textContent('#fg-exemplar-caption');
  const count = Number(/(\d+) pixels/.exec(caption)[1]);
  assert.ok(count > 100, caption);
  // Erase part of the exemplar's map: fewer feature pixels.
  await page.check('input[name="fg-brush"][value="erase"]');
  const box = await page.locator('#fg-exemplar').boundingBox();
  await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.3);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.6, box.y + box.height * 0.35, { steps: 6 });
  await page.mouse.up();
  const after = Number(/(\d+) pixels/.exec(await page.textContent('#fg-exemplar-caption'))[1]);
  assert.ok(after < count, `erasing removed features: ${count} -> ${after}`);
  await page.check('input[name="fg-brush"][value="off"]');
  await page.click('#step');
  await page.waitForSelector('body[data-feature-patches="1"]');
  await page.click('#step');
  await page.waitForSelector('body[data-feature-patches="2"]');
  // Graph-cut placement lays patches unbent: its readout says so, and the warp box is off.
  assert.match(await page.textContent('#fg-readout'), /patch 2\/\d+ .* context features · no warp \(graph-cut placement\)/);
  assert.equal(await page.isDisabled('#fg-warp'), true);
  assert.match(await page.getAttribute('#fg-warp-label', 'title'), /scan placement's patches only/);
  assert.equal(await page.isDisabled('#fg-anatomy-on'), false);
  await page.click('#run');
  await page.waitForSelector('body[data-features-done="true"]', { timeout: 120_000 });
  // getAttribute gives null for a missing attribute, and Number(null) is a finite 0.
  const ours = Number(await page.getAttribute('#fg-quality', 'data-broken') ?? NaN);
  const theirs = Number(await page.getAttribute('#fg-graphcut-caption', 'data-broken') ?? NaN);
  assert.ok(Number.isFinite(ours) && Number.isFinite(theirs), `${ours} ${theirs}`);
  // And on the carried (synthesised) maps: the curves each method's seams cut.
  const oursSeams = Number(await page.getAttribute('#fg-quality', 'data-broken-seams') ?? NaN);
  const theirsSeams = Number(await page.getAttribute('#fg-graphcut-caption', 'data-broken-seams') ?? NaN);
  assert.ok(Number.isFinite(oursSeams) && Number.isFinite(theirsSeams), `${oursSeams} ${theirsSeams}`);
  assert.match(await page.textContent('#fg-graphcut-caption'), /broken features -?\d+\.\d, at seams -?\d+\.\d \(feature-guided: -?\d+\.\d, at seams -?\d+\.\d; lower is better\)/);
  assert.doesNotMatch(await page.textContent('#fg-graphcut-caption'), /NaN/);
  const pixels = await canvasPixels(page, 'fg-map');
  assert.ok(pixels.some((v, i) => i % 4 === 3 && v === 255), 'the synthesised feature map is drawn');
  await page.screenshot({ path: `${RESULTS}/features.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('the warp box works with the scan placement only, the placement anatomy with graph cut only', async () => {
  const { page, errors } = demo;
  await page.selectOption('#fg-placement', 'scan');
  assert.equal(await page.isDisabled('#fg-warp'), false);
  assert.equal(await page.isDisabled('#fg-anatomy-on'), true);
  assert.match(await page.getAttribute('#fg-anatomy-label', 'title'), /not for the scan placement/);
  for (let n = 1; n <= 2; n++) {
    await page.click('#step');
    await page.waitForSelector(`body[data-feature-patches="${n}"]`);
  }
  // The second patch meets the first: its readout reports the correspondences and the warp.
  assert.match(await page.textContent('#fg-readout'), /patch 2\/\d+ .* context features · \d+ correspondences · warp: \w+/);
  await page.selectOption('#fg-placement', 'graphcut');
  assert.equal(await page.isDisabled('#fg-warp'), true);
  assert.equal(await page.isDisabled('#fg-anatomy-on'), false);
  assert.deepEqual(errors, []);
});

test('an uploaded exemplar smaller than the default patch runs with the options untouched', async () => {
  const { page, errors } = demo;
  // A 48x48 crop of tiles_64, made on a canvas: the patch field still says 64.
  const png = await page.evaluate(async () => {
    const image = new Image();
    image.src = './samples/tiles_64.png';
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = 48;
    canvas.getContext('2d').drawImage(image, 0, 0);
    const blob = await new Promise((done) => canvas.toBlob(done, 'image/png'));
    return Array.from(new Uint8Array(await blob.arrayBuffer()));
  });
  await page.setInputFiles('#upload', { name: 'small.png', mimeType: 'image/png', buffer: Buffer.from(png) });
  await page.waitForSelector('body[data-exemplar="small.png"]');
  // The field back at its default (the first test set 32).
  await page.fill('#fg-patch', '64');
  await page.click('#run');
  await page.waitForSelector('body[data-features-done="true"]', { timeout: 120_000 });
  assert.equal(await page.isHidden('#error'), true);
  assert.doesNotMatch(await page.textContent('#fg-readout'), /error|larger than/i);
  await page.screenshot({ path: `${RESULTS}/features-small-exemplar.png`, fullPage: true });
  assert.deepEqual(errors, []);
});
