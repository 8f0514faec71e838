// Usable by everyone: keyboard only (Tab, arrows, Enter, Space; no clicks)
// picks a sample, selects a method in the tablist and runs it to done; every control of every
// panel has an accessible name (from Chromium's accessibility tree); focus is visible.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { finishedOptimizationForPaint, openDemo, RESULTS, tabTo } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

const focused = (page) => page.evaluate(() => {
  const el = document.activeElement;
  const style = getComputedStyle(el);
  return { id: el.id, sample: el.dataset.sample, panel: el.dataset.panel, outline: style.outlineStyle, outlineWidth: style.outlineWidth };
});

test('keyboard only: a sample, the graph-cut tab, a small output, Run to done', async () => {
  const { page, errors } = demo;
  // The samples are one Tab stop: from the page's start, Tab reaches the pressed sample, whose
  // left neighbour is tiles 64x64.
  await page.keyboard.press('Tab');
  assert.match((await focused(page)).id, /^$/, 'the skip link comes first');
  const presses = await tabTo(page, '#samples button');
  assert.ok(presses <= 2, `the samples are the first stop after the skip link (${presses} presses)`);
  assert.equal((await focused(page)).sample, 'tiles_128', 'the Tab stop is the pressed sample');
  await page.keyboard.press('ArrowLeft');
  assert.equal((await focused(page)).sample, 'tiles_64');
  await page.keyboard.press('Enter');
  await page.waitForSelector('body[data-exemplar="tiles 64×64"]');
  // One Tab leaves the sample grid (it is a single stop).
  await page.keyboard.press('Tab');
  assert.equal((await focused(page)).sample, undefined, 'one Tab leaves the grid');

  // The method tabs: one stop, arrows move, Enter selects; the roving tabindex follows.
  await tabTo(page, '#methods [role="tab"]');
  assert.equal((await focused(page)).panel, 'optimization');
  const focus = await focused(page);
  assert.notEqual(focus.outline, 'none', 'focus is visible');
  await page.keyboard.press('ArrowRight');
  assert.equal((await focused(page)).panel, 'graphcut');
  assert.equal(await page.getAttribute('#tab-graphcut', 'aria-selected'), 'false', 'arrows move focus only');
  await page.screenshot({ path: `${RESULTS}/keyboard-focus.png`, clip: { x: 0, y: 0, width: 1400, height: 260 } });
  await page.keyboard.press('Enter');
  assert.equal(await page.getAttribute('#tab-graphcut', 'aria-selected'), 'true');
  assert.equal(await page.getAttribute('#method-options', 'aria-labelledby'), 'tab-graphcut');
  assert.equal(await page.getAttribute('#tab-graphcut', 'aria-controls'), 'method-options');
  const tabindex = await page.$$eval('#methods [role="tab"]', (tabs) => tabs.map((t) => t.tabIndex));
  assert.deepEqual(tabindex, tabindex.map((_, i) => (i === 1 ? 0 : -1)), 'roving tabindex');
  await page.keyboard.press('End');
  assert.equal((await focused(page)).panel, 'compare');
  await page.keyboard.press('Home');
  await page.keyboard.press('ArrowRight');
  assert.equal((await focused(page)).panel, 'graphcut');

  // A 64x64 output: type into the size fields; Tab commits each (their change event).
  for (const id of ['out-width', 'out-height']) {
    await tabTo(page, `#${id}`);
    await page.keyboard.press('Control+A');
    await page.keyboard.type('64');
  }
  await page.keyboard.press('Tab');
  assert.equal(await page.inputValue('#out-height'), '64');
  // Shift+Tab back to Run, Space presses it.
  for (let n = 0; n < 10 && (await focused(page)).id !== 'run'; n++) await page.keyboard.press('Shift+Tab');
  assert.equal((await focused(page)).id, 'run');
  await page.keyboard.press('Space');
  await page.waitForSelector('body[data-graphcut-done="true"]', { timeout: 60_000 });
  assert.equal(await page.evaluate(() => document.getElementById('output-canvas').width), 64);
  assert.equal(await page.textContent('#status'), 'done');
  assert.deepEqual(errors, []);
});

/** The unnamed controls in the page's accessibility tree. */
async function unnamedControls(page) {
  const tree = await page.locator('body').ariaSnapshot();
  const found = [];
  // A control line with a name reads `- button "Run"`; without one `- button`, `- checkbox
  // [checked]` or `- spinbutton: "256"` (its value, not a name).
  for (const line of tree.split('\n')) {
    const control = line.match(/^\s*- (button|checkbox|radio|textbox|spinbutton|combobox|slider|tab|switch|searchbox)\b(.*)$/);
    if (control && !control[2].startsWith(' "')) found.push(line.trim());
  }
  return found;
}

test('every control of every panel has an accessible name', async () => {
  const { page, errors } = demo;
  // Control: controls without names are found.
  await page.evaluate(() => document.getElementById('method-options').insertAdjacentHTML('beforeend',
    '<span id="probe"><input type="checkbox" checked><input type="number" value="3"><select><option>a</option></select><button></button></span>'));
  assert.equal((await unnamedControls(page)).length, 4, 'the check finds four unnamed probes');
  await page.evaluate(() => document.getElementById('probe').remove());
  const unnamed = [];
  for (const panel of await page.$$eval('#methods [role="tab"]', (tabs) => tabs.map((t) => t.dataset.panel))) {
    await page.click(`#tab-${panel}`);
    // A panel with stages inside its options (texture design): every stage.
    const stages = await page.$$eval('#method-options [role="tab"][data-stage]', (tabs) => tabs.map((t) => t.dataset.stage));
    for (const stage of stages.length ? stages : [null]) {
      if (stage) await page.click(`#method-options [data-stage="${stage}"]`);
      for (const line of await unnamedControls(page)) unnamed.push(`${panel}${stage ? `/${stage}` : ''}: ${line}`);
    }
  }
  assert.deepEqual(unnamed, []);
  assert.deepEqual(errors, []);
});

test('keyboard only: a painted stroke of soft constraints pulls the texture toward the paint', async () => {
  const { page, errors } = demo;
  const redness = await finishedOptimizationForPaint(page);
  const before = await redness();
  await page.fill('#to-colour', '#ff0000');
  // From here on the keyboard only: Space ticks "paint", Tab reaches the canvas.
  await page.focus('#to-paint');
  await page.keyboard.press('Space');
  assert.equal(await page.isChecked('#to-paint'), true);
  await tabTo(page, '#output-canvas');
  assert.match(await page.getAttribute('#output-canvas', 'aria-description'), /hold Space to paint/);
  // The cursor starts in the middle; 18 steps of 1/50 left puts it at 0.14. Three passes along
  // the middle band with Space held, as the pointer test paints.
  for (let n = 0; n < 18; n++) await page.keyboard.press('ArrowLeft');
  assert.equal(await page.getAttribute('#output-canvas', 'data-brush'), '0.14,0.50');
  await page.keyboard.down(' ');
  for (const dy of [0, -1, 2]) {
    if (dy < 0) await page.keyboard.press('ArrowUp');
    if (dy > 0) for (let n = 0; n < dy; n++) await page.keyboard.press('ArrowDown');
    const key = dy < 0 ? 'ArrowLeft' : 'ArrowRight';
    for (let n = 0; n < 36; n++) await page.keyboard.press(key);
  }
  assert.equal(await page.isVisible('.brush-ring.painting'), true, 'the cursor shows the stroke');
  await page.keyboard.up(' ');
  await page.waitForSelector('body[data-constraints-set="1"]');
  await page.waitForFunction(() => document.getElementById('status').textContent === 'done', null, { timeout: 60_000 });
  const after = await redness();
  assert.ok(after > before + 30, `red minus green in the painted band: ${before.toFixed(1)} -> ${after.toFixed(1)}`);
  await page.screenshot({ path: `${RESULTS}/keyboard-paint.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('keyboard only: a merge painted with the keyboard completes', async () => {
  const { page, errors } = demo;
  await page.click('#tab-merge');
  await page.click('button[data-sample="tiles_128"]');
  await page.waitForSelector('body[data-exemplar="tiles 128×128"]');
  const stroke = async (brush, steps) => {
    await page.focus(`input[name="mg-brush"][value="${brush}"]`);
    await page.keyboard.press('Space');
    await tabTo(page, '#output-canvas');
    for (let n = 0; n < 25; n++) await page.keyboard.press('ArrowUp');
    for (let n = 0; n < Math.abs(steps); n++) await page.keyboard.press(steps < 0 ? 'ArrowLeft' : 'ArrowRight');
    await page.keyboard.down(' ');
    for (let n = 0; n < 50; n++) await page.keyboard.press('ArrowDown');
    await page.keyboard.up(' ');
  };
  await stroke(1, -3);
  await stroke(2, 6);
  await page.focus('#run');
  await page.keyboard.press('Space');
  await page.waitForSelector('body[data-merge-done="true"]', { timeout: 30_000 });
  assert.match(await page.textContent('#mg-readout'), /merged · cut cost/);
  assert.deepEqual(errors, []);
});
