// The "Graph-cut merge" panel with more than two images in headless Chromium: a third image placed
// below the others grows the output to the box around all three, a stroke painted for it (part of
// it on its top edge, which the brush leaves off) holds up in the merge, and the result has pixels
// of all three images. The list takes at most eight images, a removed one takes its row and its
// paint with it, a link brings the list back, the options fit a phone, and the keyboard brush
// paints for any image of the list.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, openDemo, openPanel, RESULTS, tabTo } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

const canvasSize = (page) => page.$eval('#output-canvas', (c) => [c.width, c.height]);

/** The numbers of a comma-separated data- attribute of the merge's readout. */
const readoutFigures = async (page, name) => (await page.getAttribute('#mg-readout', `data-${name}`)).split(',').map(Number);

const redPixels = (pixels) => {
  let n = 0;
  for (let i = 0; i < pixels.length; i += 4) if (pixels[i] === 255 && pixels[i + 1] === 40 && pixels[i + 2] === 40) n++;
  return n;
};

/** Sets a row's number input as typing and leaving it would. */
async function setNumber(page, selector, value) {
  await page.fill(selector, String(value));
  await page.dispatchEvent(selector, 'change');
}

const visibleRows = (page) => page.$$eval('[id^="mg-source-"]', (rows) => rows.filter((r) => !r.hidden).length);

test('a third image below the others: the output is the box around all three, and its paint holds', async () => {
  const { page, errors } = demo;
  await openPanel(page, 'merge', 'tiles_128');
  // The exemplar at (0, 0) and the second image at (64, 0): 192 x 128.
  await page.waitForFunction(() => document.getElementById('output-canvas').width === 192);
  assert.equal(await visibleRows(page), 2);
  await page.click('#mg-add');
  assert.equal(await visibleRows(page), 3);
  await page.selectOption('#mg-source-2 .mg-image', 'grass_128');
  await setNumber(page, '#mg-source-2 .mg-x', 40);
  await setNumber(page, '#mg-source-2 .mg-y', 96);
  // Three 128 x 128 images at (0, 0), (64, 0) and (40, 96): the box is 192 x 224.
  await page.waitForFunction(() => {
    const c = document.getElementById('output-canvas');
    return c.width === 192 && c.height === 224 && document.getElementById('mg-readout').dataset.painted === '0,0,0';
  });
  await page.waitForFunction(() => location.search.includes('mg-sources=0.0-sand_128.64.0-grass_128.40.96'));
  await page.locator('#output-canvas').scrollIntoViewIfNeeded();
  await page.screenshot({ path: `${RESULTS}/merge-sources-preview.png`, fullPage: true });

  // One stroke for the third image, down from above its top edge (y = 96) into the part only it
  // covers. Pixels above the edge and on it, where the first two lie on both sides, stay unpainted:
  // the merge would refuse them.
  await page.check('input[name="mg-brush"][value="3"]');
  await page.locator('#output-canvas').scrollIntoViewIfNeeded();
  const box = await page.locator('#output-canvas').boundingBox();
  const at = (x, y) => [box.x + ((x + 0.5) / 192) * box.width, box.y + ((y + 0.5) / 224) * box.height];
  await page.mouse.move(...at(100, 84));
  await page.mouse.down();
  await page.mouse.move(...at(100, 200), { steps: 24 });
  await page.mouse.up();
  const painted = await readoutFigures(page, 'painted');
  assert.deepEqual(painted.slice(0, 2), [0, 0]);
  assert.ok(painted[2] > 500, `${painted[2]} pixels painted for the third image`);

  await page.click('#run');
  await page.waitForSelector('body[data-merge-done="true"]', { timeout: 60_000 });
  assert.equal(await page.isHidden('#error'), true, 'the merge took the paint');
  assert.match(await page.textContent('#mg-readout'), /merged · cut cost .* pixels from each image: 1: \d+ · 2: \d+ · 3: \d+/);
  assert.deepEqual(await canvasSize(page), [192, 224]);
  const counts = await readoutFigures(page, 'source-pixels');
  assert.equal(counts.length, 3);
  // Every pixel one of the images covers comes from one of them: the 192 x 128 band of the first
  // two, and the 128 x 96 the third adds below it.
  assert.equal(counts.reduce((a, b) => a + b, 0), 192 * 128 + 128 * 96);
  assert.ok(counts[2] >= 128 * 96, `the third image gave ${counts[2]} pixels, at least the part only it covers`);
  assert.ok(counts[0] > 0 && counts[1] > 0, `the first two gave ${counts[0]} and ${counts[1]} pixels`);
  assert.ok(redPixels(await canvasPixels(page)) > 20, 'the seams are drawn');
  await page.locator('#output-canvas').scrollIntoViewIfNeeded();
  await page.screenshot({ path: `${RESULTS}/merge-sources.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('at most eight images; a removed one takes its row and its paint, and a link brings the list back', async () => {
  const { page, errors } = demo;
  // From the three images of the test above: five more fill the list.
  for (let n = 3; n < 8; n++) await page.click('#mg-add');
  assert.equal(await visibleRows(page), 8);
  assert.equal(await page.isDisabled('#mg-add'), true, '"Add image" is greyed at eight');
  await page.waitForFunction(() => document.getElementById('mg-readout').dataset.painted?.split(',').length === 8);
  const painted = await readoutFigures(page, 'painted');
  assert.ok(painted[2] > 500, 'the third image keeps its paint while others are added');

  // Removing the third: the fourth moves up into its row, its paint goes, and the brush for it
  // gives way to the first image's.
  const fourth = await page.$eval('#mg-source-3', (row) => [row.querySelector('.mg-image').value, row.querySelector('.mg-x').value, row.querySelector('.mg-y').value]);
  await page.click('#mg-source-2 .mg-remove');
  assert.equal(await visibleRows(page), 7);
  assert.equal(await page.isDisabled('#mg-add'), false);
  const row = await page.$eval('#mg-source-2', (r) => [r.querySelector('.mg-image').value, r.querySelector('.mg-x').value, r.querySelector('.mg-y').value]);
  assert.deepEqual(row, fourth);
  assert.equal(await page.isChecked('input[name="mg-brush"][value="1"]'), true);
  await page.waitForFunction(() => document.getElementById('mg-readout').dataset.painted?.split(',').length === 7);
  assert.deepEqual(await readoutFigures(page, 'painted'), [0, 0, 0, 0, 0, 0, 0]);

  // The link keeps the list: the page opened from it shows the same seven rows.
  await page.waitForFunction(() => new URLSearchParams(location.search).get('mg-sources')?.split('-').length === 7);
  const sources = new URLSearchParams(new URL(page.url()).search).get('mg-sources');
  await page.goto(page.url());
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  await page.waitForFunction((n) => document.querySelectorAll('[id^="mg-source-"]:not([hidden])').length === n, 7);
  assert.equal(await page.inputValue('#mg-sources'), sources);
  const rows = await page.$$eval('[id^="mg-source-"]:not([hidden])', (list) => list.map((r) => [r.querySelector('.mg-image')?.value ?? 'exemplar', r.querySelector('.mg-x').value, r.querySelector('.mg-y').value].join('.')));
  assert.equal(rows.slice(1).join('-'), sources.split('-').slice(1).join('-'));
  assert.deepEqual(errors, []);
});

test('keyboard only: the brush of the third of seven images paints, and the merge of all seven runs', async () => {
  const { page, errors } = demo;
  // The page opened from the link above: seven images, the third (grass) at (96, 64), the box
  // 256 x 320 with its middle on the third image and on no earlier one.
  assert.deepEqual(await canvasSize(page), [256, 320]);
  await page.focus('input[name="mg-brush"][value="3"]');
  await page.keyboard.press('Space');
  assert.equal(await page.isChecked('input[name="mg-brush"][value="3"]'), true);
  const presses = await tabTo(page, '#output-canvas');
  assert.ok(presses < 30, `${presses} Tab presses from the brush to the canvas`);
  await page.keyboard.down(' ');
  for (let n = 0; n < 3; n++) await page.keyboard.press('ArrowDown');
  await page.keyboard.up(' ');
  const painted = await readoutFigures(page, 'painted');
  assert.equal(painted.length, 7);
  assert.ok(painted[2] > 100, `${painted[2]} pixels painted for the third image with the keyboard`);
  assert.equal(painted.reduce((a, b) => a + b, 0), painted[2]);

  await page.focus('#run');
  await page.keyboard.press('Space');
  await page.waitForSelector('body[data-merge-done="true"]', { timeout: 60_000 });
  const counts = await readoutFigures(page, 'source-pixels');
  assert.equal(counts.length, 7);
  assert.ok(counts[2] >= painted[2], `the third image gave ${counts[2]} pixels, its ${painted[2]} painted ones among them`);

  await page.locator('#output-canvas').scrollIntoViewIfNeeded();
  await page.screenshot({ path: `${RESULTS}/merge-sources-seven.png`, fullPage: true });
  // Every control of the rows has a name (an unnamed one reads `- spinbutton: "40"`).
  const tree = await page.locator('#mg-sources-list').ariaSnapshot();
  const unnamed = tree.split('\n').filter((line) => /^\s*- (button|radio|spinbutton|combobox)\b(?! ")/.test(line));
  assert.deepEqual(unnamed, []);
  assert.match(tree, /spinbutton "image 3: y"/);

  // The options with seven rows wrap on a phone instead of widening the page.
  await page.setViewportSize({ width: 390, height: 844 });
  const widths = await page.evaluate(() => [document.documentElement.scrollWidth, window.innerWidth]);
  assert.ok(widths[0] <= widths[1], `scrollWidth ${widths[0]} > ${widths[1]} at 390 px`);
  await page.setViewportSize({ width: 1400, height: 900 });
  assert.deepEqual(errors, []);
});
