// The "Compare" panel: one exemplar and seed through texture optimization,
// graph cut and feature-guided synthesis side by side, then plain against wavelet energies; each
// result with its quality metrics and wall time; the history scrubs all canvases together.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { openDemo, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

/** For each figure: its method, time line, quality line, and how many distinct values its canvas holds. */
const figures = (page) =>
  page.$$eval('.compare-item', (items) => items.map((item) => {
    const canvas = item.querySelector('canvas');
    const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
    return {
      id: item.id,
      time: item.querySelector('.compare-time').textContent,
      quality: item.querySelector('.quality').textContent,
      coherence: Number(item.querySelector('.quality').dataset.coherence),
      flat: Number(item.querySelector('.quality').dataset.flat),
      distinct: new Set(data).size,
      size: [canvas.width, canvas.height],
    };
  }));

async function runToDone(page) {
  await page.click('#run');
  await page.waitForSelector('body[data-compare-done="true"]', { timeout: 90_000 });
}

test('three methods side by side, each with metrics and time', async () => {
  const { page, errors } = demo;
  await page.click('button[data-panel="compare"]');
  await page.click('button[data-sample="tiles_64"]');
  await page.waitForSelector('body[data-exemplar="tiles 64×64"]');
  await page.fill('#out-width', '64');
  await page.fill('#out-height', '64');
  await page.dispatchEvent('#out-height', 'change');
  assert.equal(await page.isHidden('#output-canvas'), true, 'the single output gives way to the grid');
  await runToDone(page);
  const shown = await figures(page);
  assert.deepEqual(shown.map((f) => f.id), ['cmp-item-optimization', 'cmp-item-graphcut', 'cmp-item-features']);
  for (const f of shown) {
    assert.deepEqual(f.size, [64, 64], f.id);
    assert.match(f.time, /^done · \d+ steps · \d+\.\d\d s$/, f.id);
    assert.match(f.quality, /coherence .* completeness .* histogram .* flat/, f.id);
    assert.ok(f.coherence > 0 && f.coherence < 0.01, `${f.id} coherence ${f.coherence}`);
    assert.ok(f.distinct > 50, `${f.id} is a texture`);
  }
  // The side table: a row per method, the best of each column marked.
  const table = await page.$$eval('#cmp-table tbody tr', (rows) => rows.map((r) => ({
    name: r.querySelector('th').textContent,
    cells: [...r.querySelectorAll('td')].map((td) => ({ text: td.textContent, best: td.classList.contains('best') })),
  })));
  assert.deepEqual(table.map((r) => r.name), ['Texture optimization', 'Graph cut', 'Feature-guided']);
  for (let c = 0; c < 5; c++) assert.ok(table.some((r) => r.cells[c].best), `column ${c} has a best`);
  assert.match(table[0].cells[0].text, /^\d\.\de-\d$/);
  // The detail metric: each method's flat fraction as on its card, the one nearest
  // the exemplar's own 10% in bold.
  const flats = shown.map((f) => f.flat);
  table.forEach((r, i) => assert.equal(r.cells[3].text, `${(flats[i] * 100).toFixed(1)}%`, r.name));
  const nearest = Math.min(...flats.map((f) => Math.abs(f - 0.1)));
  table.forEach((r, i) => assert.equal(r.cells[3].best, Math.abs(flats[i] - 0.1) === nearest, r.name));
  assert.match(table[0].cells[4].text, /^\d+\.\d\d s$/);
  // The canvases line up (the captions wrap differently).
  const tops = await page.$$eval('.compare-item canvas', (cs) => cs.map((c) => Math.round(c.getBoundingClientRect().top)));
  assert.equal(new Set(tops).size, 1, `canvas tops ${tops}`);
  const fits = await page.$eval('#cmp-table', (t) => t.getBoundingClientRect().right <= t.closest('.panel').getBoundingClientRect().right);
  assert.ok(fits, 'the table fits in the side panel');
  await page.screenshot({ path: `${RESULTS}/compare-methods.png`, fullPage: true });

  // The history keeps every canvas: its first step shows one started result and two empty ones.
  assert.ok(Number(await page.getAttribute('body', 'data-history-length')) > 3);
  await page.focus('#history-range');
  await page.keyboard.press('Home');
  const first = await figures(page);
  assert.ok(first[0].distinct > 1, 'step 1: the first method has drawn');
  assert.ok(first[2].distinct <= 2, 'step 1: the third has not started');
  await page.click('#history-live');
  assert.deepEqual((await figures(page)).map((f) => f.distinct), shown.map((f) => f.distinct));
  assert.deepEqual(errors, []);
});

test('plain against wavelet energies, picked with the preset', async () => {
  const { page, errors } = demo;
  await page.click('#cmp-preset-energies');
  assert.equal(await page.isChecked('#cmp-graphcut'), false);
  await page.waitForFunction(() => location.search.includes('cmp-haar=1'), null, { timeout: 5000 });
  await runToDone(page);
  const shown = await figures(page);
  assert.deepEqual(shown.map((f) => f.id), ['cmp-item-optimization', 'cmp-item-haar', 'cmp-item-daubechies']);
  for (const f of shown) {
    assert.match(f.time, /^done · \d+ steps/, f.id);
    assert.match(f.quality, /coherence/, f.id);
  }
  await page.screenshot({ path: `${RESULTS}/compare-energies.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('fewer than two picked: the run does not start and says why', async () => {
  const { page } = demo;
  await page.uncheck('#cmp-haar');
  await page.uncheck('#cmp-daubechies');
  assert.match(await page.textContent('#cmp-readout'), /pick two or more/);
  await page.click('#step');
  await page.waitForTimeout(300);
  assert.equal(await page.getAttribute('body', 'data-history-length'), '0');
});
