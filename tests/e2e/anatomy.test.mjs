// Placement anatomy in headless Chromium: with the view on, each graph-cut
// placement shows its cost surface with the drawn offset among the cheapest, the probabilities
// of eq. 3, and the seam graph with a minimum cut; the hover readout names a pixel's arcs.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { openDemo, openPanel, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

/** The drawn offset's ring (cyan) is on the cost canvas, and hovering the graph names a pixel's arcs. */
async function assertMarkedAndHoverable(page) {
  const cyan = await page.$eval('#gc-cost', (c) => {
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 120 && d[i + 1] > 180 && d[i + 2] > 200) n++;
    return n;
  });
  assert.ok(cyan > 10, `${cyan} marker pixels`);
  await page.hover('#gc-graph');
  assert.match(await page.textContent('#gc-graph-readout'), /pixel \(\d+, \d+\): .*arc right/);
}

test('the placement anatomy shows the cost surface, the probabilities and the cut', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'graphcut', 'gravel_128', 256);
  await page.check('#gc-anatomy-on');
  assert.equal(await page.isVisible('#gc-anatomy'), true);
  const ranks = [];
  for (let n = 1; n <= 6; n++) {
    await page.click('#step');
    await page.waitForSelector(`body[data-anatomy-patches="${n}"]`);
    // The first patch is placed at random (nothing to match): its surface is flat.
    if (n === 1) continue;
    const legend = await page.$eval('#gc-cost-legend', (e) => ({ ...e.dataset }));
    assert.ok(Number(legend.offsets) > 100, `${legend.offsets} candidate offsets`);
    assert.ok(Number(legend.chosenProbability) > 0, 'the drawn offset had a chance');
    ranks.push(Number(legend.chosenRank));
    assert.match(await page.textContent('#gc-explain'), /Covering the output.*section 4/s);
    const cut = Number(await page.getAttribute('#gc-graph', 'data-cut-pixels'));
    assert.ok(cut > 20, `a seam of ${cut} pixels is drawn`);
  }
  // With k = 0.01, eq. 3 draws from the cheapest few per cent of offsets: the marked offset lies
  // in the surface's minimum region.
  assert.ok(Math.max(...ranks) < 0.05, `ranks of the drawn offsets: ${ranks}`);
  await assertMarkedAndHoverable(page);
  await page.screenshot({ path: `${RESULTS}/anatomy-graphcut.png`, fullPage: true });
  // Off again: nothing more is recorded and the view hides.
  await page.uncheck('#gc-anatomy-on');
  assert.equal(await page.isVisible('#gc-anatomy'), false);
  assert.deepEqual(errors, []);
});

test('the step anatomy shows the E-step output and the M-step matches apart', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'optimization', 'gravel_64', 96);
  await page.check('#to-anatomy-on');
  assert.equal(await page.isVisible('#to-anatomy'), true);
  const halves = [];
  let eImage = null;
  let mImage = null;
  for (let n = 1; n <= 5; n++) {
    await page.click('#step');
    await page.waitForSelector(`body[data-steps="${n}"]`);
    const half = await page.getAttribute('body', 'data-half');
    halves.push(half);
    const pixels = await page.$eval('#output-canvas', (c) => Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data));
    if (half === 'e-step') eImage = pixels;
    else if (eImage && !mImage) mImage = pixels;
  }
  // A level's first M-step, then E-step and M-step in turn.
  assert.deepEqual(halves.slice(0, 3), ['first-match', 'e-step', 'm-step'], halves.join(' '));
  assert.ok(eImage && mImage, 'an E-step and the M-step after it were shown');
  assert.equal(eImage.length, mImage.length);
  let differing = 0;
  for (let i = 0; i < eImage.length; i += 4) if (eImage[i] !== mImage[i] || eImage[i + 1] !== mImage[i + 1]) differing++;
  assert.ok(differing > eImage.length / 4 / 10, `${differing} pixels differ between the E-step and M-step views`);
  // The explanation follows the step: the last was an E-step or an M-step, and names the paper.
  assert.match(await page.textContent('#to-explain'), /(M-step|E-step).*Read more/s);
  await page.click('#to-explain summary');
  assert.match(await page.textContent('#to-explain .cite'), /Kwatra.*2005.*section 3/);
  assert.ok(Number(await page.getAttribute('#to-weights', 'data-nodes')) > 10, 'the IRLS weights are drawn');
  await page.hover('#output-canvas', { position: { x: 60, y: 60 } });
  assert.match(await page.textContent('#to-node-readout'), /node \(\d+, \d+\).*z_p at exemplar \(\d+, \d+\); .*IRLS weight/);
  await page.screenshot({ path: `${RESULTS}/anatomy-optimization.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('every method panel explains what is on screen and cites its paper', async () => {
  const { page, errors } = demo;
  const panels = await page.$$eval('#methods button', (b) => b.map((x) => x.dataset.panel));
  const cited = [];
  for (const panel of panels) {
    if (panel === 'compare') continue; // its cells carry each method's own name
    await page.click(`button[data-panel="${panel}"]`);
    const text = await page.$eval('#side .explain', (e) => e.textContent);
    assert.ok(text.length > 60, `${panel}: "${text}"`);
    const cite = await page.$eval('#side .explain .cite', (e) => e.textContent);
    assert.match(cite, /(Kwatra|Shen|Wu & Yu).*(19|20)\d\d.*section/, panel);
    cited.push(panel);
  }
  assert.ok(cited.length >= 7, cited.join(', '));
  assert.deepEqual(errors, []);
});

test('feature-guided graph-cut placements show their anatomy too', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'features', 'brick_128', 192);
  await page.check('#fg-anatomy-on');
  assert.equal(await page.isVisible('#gc-anatomy'), true);
  for (let n = 1; n <= 3; n++) {
    await page.click('#step');
    await page.waitForSelector(`body[data-feature-patches="${n}"]`);
  }
  const legend = await page.$eval('#gc-cost-legend', (e) => ({ ...e.dataset }));
  assert.ok(Number(legend.offsets) > 50, `${legend.offsets} candidate offsets`);
  // The probabilities are the draw's: over the 64 best offsets by colour (featureCandidates),
  // by colour plus feature cost, not graph cut's over every offset.
  const drawable = Number(legend.drawable);
  assert.ok(drawable >= 1 && drawable <= 64 && drawable < Number(legend.offsets), `${drawable} drawable of ${legend.offsets}`);
  assert.ok(Number(legend.chosenProbability) > 0, 'the drawn offset could be drawn');
  assert.ok(Number(await page.getAttribute('#gc-graph', 'data-cut-pixels')) > 10, 'a seam is drawn');
  assert.match(await page.textContent('#gc-anatomy h3'), /feature cost re-ranks/);
  assert.match(await page.textContent('#gc-cost-legend'), /best offsets by colour, from colour plus feature cost/);
  // Graph-cut placement draws no warp, and its explanation says so (the scan placement's does).
  assert.match(await page.textContent('#fg-explain'), /No warp here/);
  await page.screenshot({ path: `${RESULTS}/anatomy-features.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('the flow panel splits a frame into E-step and M-step beside its warped previous frame', async () => {
  const { page, errors } = demo;
  await page.setViewportSize({ width: 1280, height: 720 });
  await openPanel(page, 'flow', 'gravel_64', 64);
  await page.fill('#fl-frames', '3');
  await page.dispatchEvent('#fl-frames', 'change');
  await page.check('#fl-anatomy-on');
  assert.equal(await page.isVisible('#to-anatomy'), true);
  const pixels = () => page.$eval('#output-canvas', (c) => Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data));
  // Frame 1 (index 0) is texture optimization split the same way; then frame 2's halves.
  const halves = [];
  let eImage = null;
  let mImage = null;
  for (let n = 1; n <= 120 && !mImage; n++) {
    await page.click('#step');
    await page.waitForSelector(`body[data-flow-steps="${n}"]`);
    const { flowHalf: half, flowFrame: frame } = await page.$eval('body', (b) => ({ ...b.dataset }));
    if (frame === '0') {
      if (halves.length < 3) halves.push(half);
      continue;
    }
    if (half === 'e-step') eImage = await pixels();
    else if (eImage) mImage = await pixels();
  }
  assert.deepEqual(halves, ['first-match', 'e-step', 'm-step'], 'frame 1 starts with a level\'s halves');
  assert.ok(eImage && mImage, 'a later frame showed an E-step and the M-step after it');
  let differing = 0;
  for (let i = 0; i < eImage.length; i += 4) if (eImage[i] !== mImage[i] || eImage[i + 1] !== mImage[i + 1]) differing++;
  assert.ok(differing > eImage.length / 4 / 10, `${differing} pixels differ between the E-step and M-step views`);
  // The warped previous frame is drawn, opaque where the flow brought something in.
  const warped = await page.$eval('#fl-warped', (c) => {
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let opaque = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i] === 255) opaque++;
    return { opaque, pixels: d.length / 4, width: c.width };
  });
  assert.equal(warped.width, 64);
  assert.ok(warped.opaque > warped.pixels / 2, `${warped.opaque} of ${warped.pixels} warped pixels opaque`);
  assert.match(await page.textContent('#fl-warped-legend'), /Frame [2-9]/);
  assert.ok(Number(await page.getAttribute('#to-weights', 'data-nodes')) > 10, 'the IRLS weights are drawn');
  assert.match(await page.textContent('#fl-explain'), /(M-step|E-step) of a flow frame/);
  await page.click('#fl-explain summary');
  assert.match(await page.textContent('#fl-explain .cite'), /Kwatra.*2005.*section 4\.1/);
  await page.hover('#output-canvas', { position: { x: 40, y: 40 } });
  assert.match(await page.textContent('#to-node-readout'), /node \(\d+, \d+\).*z_p at exemplar \(\d+, \d+\); .*IRLS weight/);
  await page.screenshot({ path: `${RESULTS}/anatomy-flow.png`, fullPage: false });
  await page.screenshot({ path: `${RESULTS}/anatomy-flow-full.png`, fullPage: true });
  await page.uncheck('#fl-anatomy-on');
  assert.equal(await page.isVisible('#to-anatomy'), false);
  await page.setViewportSize({ width: 1400, height: 900 });
  assert.deepEqual(errors, []);
});

test('the video panel shows a placement\'s cost slice with the drawn offset among the cheapest', async () => {
  const { page, errors } = demo;
  await page.setViewportSize({ width: 1280, height: 720 });
  await page.click('button[data-panel="video"]');
  await page.fill('#vt-size', '32');
  await page.fill('#vt-frames', '16');
  await page.selectOption('#vt-mode', 'extend');
  await page.selectOption('#vt-placement', 'sub-patch');
  await page.fill('#vt-fixed', '0');
  await page.dispatchEvent('#vt-fixed', 'change');
  await page.check('#vt-anatomy-on');
  assert.equal(await page.isVisible('#gc-anatomy'), true);
  const ranks = [];
  for (let n = 1; n <= 6; n++) {
    await page.click('#step');
    await page.waitForSelector(`body[data-video-anatomy-patches="${n}"]`);
    // The first patch is placed at random: nothing is covered to match against.
    const legend = await page.$eval('#gc-cost-legend', (e) => ({ ...e.dataset }));
    if (n === 1) {
      assert.equal(legend.offsets, undefined, 'no cost surface for the first patch');
      assert.match(await page.textContent('#vt-anatomy-slice'), /No cost surface/);
      continue;
    }
    assert.ok(Number(legend.offsets) > 20, `${legend.offsets} candidate offsets in the slice`);
    assert.ok(Number(legend.chosenProbability) > 0, 'the drawn offset had a chance');
    ranks.push(Number(legend.chosenRank));
    assert.match(await page.textContent('#vt-anatomy-slice'), /spatial offsets .* at the drawn time shift t = -?\d+ · graph: frame \d+/);
    assert.match(await page.textContent('#vt-explain'), /spatio-temporal patch.*section 7/s);
    assert.ok(Number(await page.getAttribute('#gc-graph', 'data-cut-pixels')) > 5, 'a seam is drawn in the slice');
  }
  // With k = 0.01, eq. 3 draws from the cheapest few per cent of the offsets at its time shift.
  assert.ok(Math.max(...ranks) < 0.05, `ranks of the drawn offsets: ${ranks}`);
  await assertMarkedAndHoverable(page);
  await page.screenshot({ path: `${RESULTS}/anatomy-video.png`, fullPage: false });
  await page.screenshot({ path: `${RESULTS}/anatomy-video-full.png`, fullPage: true });
  await page.setViewportSize({ width: 1400, height: 900 });
  assert.deepEqual(errors, []);
});

test('the merge panel shows its graph with the paint as constraint nodes', async () => {
  const { page, errors } = demo;
  await page.setViewportSize({ width: 1280, height: 720 });
  await openPanel(page, 'merge', 'tiles_128');
  await page.check('#mg-anatomy-on');
  assert.equal(await page.isVisible('#gc-anatomy'), true);
  assert.equal(await page.$('#gc-cost'), null, 'no cost maps: the user placed the image');
  // The second image starts at x = 64: paint inside the overlap for each image.
  const box = await page.locator('#output-canvas').boundingBox();
  const width = await page.$eval('#output-canvas', (c) => c.width);
  const stroke = async (brush, x) => {
    await page.check(`input[name="mg-brush"][value="${brush}"]`);
    await page.mouse.move(box.x + (x / width) * box.width, box.y + 10);
    await page.mouse.down();
    await page.mouse.move(box.x + (x / width) * box.width, box.y + box.height - 10, { steps: 10 });
    await page.mouse.up();
  };
  await stroke(1, 80);
  await stroke(2, 110);
  await page.click('#run');
  await page.waitForSelector('body[data-merge-done="true"]', { timeout: 30_000 });
  const graph = await page.$eval('#gc-graph', (e) => ({ ...e.dataset }));
  assert.ok(Number(graph.keepOld) > 20, `${graph.keepOld} pixels held to the composite`);
  assert.ok(Number(graph.takeNew) > 20, `${graph.takeNew} pixels held to the new image`);
  assert.ok(Number(graph.cutPixels) > 10, 'the cut is drawn');
  await page.locator('#gc-anatomy').screenshot({ path: `${RESULTS}/anatomy-merge.png` });
  assert.deepEqual(errors, []);
});
