// The step history: the store stays within its budget and keeps the run
// covered; the scrubber, worked from the keyboard, puts back exactly the pixels drawn at that
// step and moves the energy plot's marker; scrubbing while paused leaves the run as it was.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, openDemo, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

test('the store thins evenly within its budget and keeps the first step, level ends and the newest', async () => {
  const { page } = demo;
  const kept = await page.evaluate(async () => {
    const { StepHistory } = await import('/lib/history.js');
    const image = () => ({ data: new Uint8ClampedArray(1000) });
    const dropped = new Set();
    const history = new StepHistory(10_000, (entry) => dropped.add(entry.step)); // room for 10 images
    for (let step = 1; step <= 100; step++) {
      // Levels of 30, 30, 40 steps: steps 30 and 60 end a level.
      history.add({ step, levelKey: `:${step <= 30 ? 0 : step <= 60 ? 1 : 2}`, images: [image()] });
      if (history.bytes > 10_000) return { over: step };
    }
    const steps = history.entries.map((e) => e.step);
    const accounted = steps.every((s) => !dropped.has(s)) && steps.length + dropped.size === 100;
    const ends = history.strip().map((e) => e.step);
    const stride = history.stride;
    history.clear();
    return { steps, ends, stride, accounted, droppedAll: dropped.size === 100 };
  });
  assert.equal(kept.over, undefined, 'never over the budget');
  assert.ok(kept.accounted, 'every image let go is handed to onDrop (to close its bitmap), and only those');
  assert.ok(kept.droppedAll, 'clear() lets go of the rest');
  assert.equal(kept.steps[0], 1, 'the first step stays');
  assert.equal(kept.steps.at(-1), 100, 'the newest stays');
  assert.ok(kept.steps.includes(30) && kept.steps.includes(60), `level ends kept: ${kept.steps}`);
  assert.deepEqual(kept.ends, [30, 60, 100], 'the strip: each level\'s last image and the newest');
  const strided = kept.steps.filter((s) => s !== 30 && s !== 60 && s !== 100);
  for (const s of strided) assert.equal((s - 1) % kept.stride, 0, `step ${s} on the stride ${kept.stride}`);
  assert.ok(strided.at(-1) > 70, `the run stays covered to its end: ${kept.steps}`);
});

/** Cyan (#7fd1ff) pixels on the energy plot: the current-step marker. */
const markerInk = (page) =>
  page.evaluate(() => {
    const c = document.getElementById('to-energy');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - 127) < 20 && Math.abs(d[i + 1] - 209) < 20 && d[i + 2] > 230) n++;
    return n;
  });

async function setUp(page) {
  await page.click('button[data-sample="tiles_64"]');
  await page.waitForSelector('body[data-exemplar="tiles 64×64"]');
  await page.fill('#out-width', '64');
  await page.fill('#out-height', '64');
  await page.dispatchEvent('#out-height', 'change');
}

test('the scrubber puts back the pixels drawn at a step, with the plot marker on it', async () => {
  const { page, errors } = demo;
  await setUp(page);
  const drawn = [];
  for (let n = 1; n <= 3; n++) {
    await page.click('#step');
    await page.waitForSelector(`body[data-steps="${n}"]`);
    drawn.push(await canvasPixels(page));
  }
  assert.notDeepEqual(drawn[1], drawn[2], 'steps 2 and 3 differ, so equality below means something');
  await page.click('#run');
  await page.waitForSelector('body[data-optimization-done="true"]', { timeout: 60_000 });
  const final = await canvasPixels(page);
  const kept = Number(await page.getAttribute('body', 'data-history-length'));
  assert.ok(kept >= 5, `${kept} steps kept`);
  assert.equal(await markerInk(page), 0, 'no marker on the live view');

  // Keyboard only: focus the slider, Home is step 1, one ArrowRight is step 2.
  await page.focus('#history-range');
  await page.keyboard.press('Home');
  await page.keyboard.press('ArrowRight');
  assert.equal(await page.getAttribute('body', 'data-history-step'), '2');
  assert.deepEqual(await canvasPixels(page), drawn[1], 'step 2 comes back pixel for pixel');
  assert.ok((await markerInk(page)) > 20, 'the energy plot marks step 2');
  assert.match(await page.textContent('#history-info'), /showing step 2 · level 1\/\d/);
  assert.match(await page.textContent('#to-readout'), /level 1\/\d+ .* iteration 2 · energy/, 'the readout is step 2\'s');
  await page.keyboard.press('ArrowRight');
  assert.deepEqual(await canvasPixels(page), drawn[2], 'and step 3');

  // The strip: the last image of each level (Fig. 3), each a button that shows its step.
  const thumbs = await page.$$eval('#history-strip .thumb', (b) => b.map((x) => x.getAttribute('aria-label')));
  const levels = Number((await page.textContent('#to-readout')).match(/level \d+\/(\d+)/)[1]);
  assert.equal(thumbs.length, levels, `one thumbnail per level: ${thumbs.join(' | ')}`);
  await page.click('#history-strip .thumb >> nth=0');
  const firstLevelEnd = await page.getAttribute('body', 'data-history-step');
  assert.match(firstLevelEnd, /^\d+$/);
  // The strip is one Tab stop on the thumbnail shown; arrows move along it, Enter shows.
  await page.focus('#history-live');
  await page.keyboard.press('Tab');
  assert.equal(await page.evaluate(() => document.activeElement.getAttribute('aria-pressed')), 'true');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('Enter');
  assert.ok(Number(await page.getAttribute('body', 'data-history-step')) > Number(firstLevelEnd), 'the next level\'s last');
  await page.screenshot({ path: `${RESULTS}/history-scrubbed.png`, fullPage: true });

  // Back to live: the canvas shows the run's last image again and the marker goes.
  await page.click('#history-live');
  assert.equal(await page.getAttribute('body', 'data-history-step'), 'live');
  assert.deepEqual(await canvasPixels(page), final);
  assert.equal(await markerInk(page), 0);
  assert.match(await page.textContent('#to-readout'), /level (\d+)\/\1 /, 'the readout is live again');
  assert.deepEqual(errors, []);
});

test('scrubbing while paused does not change the run', async () => {
  const { page, errors } = demo;
  await page.click('#reset');
  for (let n = 1; n <= 4; n++) {
    await page.click('#step');
    await page.waitForSelector(`body[data-steps="${n}"]`);
  }
  await page.focus('#history-range');
  await page.keyboard.press('Home');
  assert.equal(await page.getAttribute('body', 'data-history-step'), '1');
  // Run goes back to the live state and carries on from step 4.
  await page.click('#run');
  await page.waitForSelector('body[data-optimization-done="true"]', { timeout: 60_000 });
  assert.equal(await page.getAttribute('body', 'data-history-step'), 'live');
  const interrupted = await canvasPixels(page);
  const steps = await page.getAttribute('body', 'data-steps');
  await page.click('#reset');
  await page.click('#run');
  await page.waitForSelector('body[data-optimization-done="true"]', { timeout: 60_000 });
  assert.equal(await page.getAttribute('body', 'data-steps'), steps, 'the same number of steps');
  assert.deepEqual(await canvasPixels(page), interrupted, 'the same output as a run nobody scrubbed');
  assert.deepEqual(errors, []);
});

test('for a method without levels the strip spreads up to 8 steps over the run', async () => {
  const { page, errors } = demo;
  await page.click('#tab-graphcut');
  await page.click('#run');
  await page.waitForSelector('body[data-graphcut-done="true"]', { timeout: 60_000 });
  const patches = Number(await page.getAttribute('body', 'data-patches'));
  const labels = await page.$$eval('#history-strip .thumb span', (s) => s.map((x) => x.textContent));
  assert.ok(patches > 8, `${patches} placements`);
  assert.equal(labels.length, 8, labels.join(', '));
  assert.equal(labels[0], 'step 1');
  assert.equal(labels.at(-1), `step ${patches}`, 'the newest is the last thumbnail');
  // A thumbnail shows its step on the canvas and the seam-cost plot.
  await page.click('#history-strip .thumb >> nth=3');
  assert.equal(await page.getAttribute('body', 'data-history-step'), labels[3].replace('step ', ''));
  await page.screenshot({ path: `${RESULTS}/history-graphcut.png`, fullPage: true });
  assert.deepEqual(errors, []);
});
