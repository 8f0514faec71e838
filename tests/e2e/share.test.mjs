// Shareable state: the URL follows the sample, method, seed, size and every
// option; the link the "Copy link" button puts on the clipboard, opened in a fresh page, restores
// all of it and reproduces the same output pixels; without a clipboard the link is shown
// selected; a stage tab inside the options (texture design) comes back from the URL too.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, openDemo, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
  const origin = new URL(demo.page.url()).origin;
  await demo.page.context().grantPermissions(['clipboard-read', 'clipboard-write'], { origin });
});
after(async () => demo?.close());

async function openFresh(url) {
  // A new browser context: nothing shared with the first page but the server.
  const page = await demo.page.context().browser().newPage({ viewport: { width: 1280, height: 720 } });
  const errors = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (msg) => msg.type() === 'error' && errors.push(msg.text()));
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  return { page, errors };
}

test('a copied link opened in a fresh page reproduces the run pixel for pixel', async () => {
  const { page, errors } = demo;
  await page.click('button[data-panel="graphcut"]');
  await page.click('button[data-sample="tiles_64"]');
  await page.waitForSelector('body[data-exemplar="tiles 64×64"]');
  await page.fill('#seed', '5');
  await page.fill('#out-width', '64');
  await page.fill('#out-height', '72');
  await page.dispatchEvent('#out-height', 'change');
  await page.fill('#gc-refine', '5');
  await page.dispatchEvent('#gc-refine', 'change');
  await page.selectOption('#gc-blend', 'feather');
  await page.check('#gc-mirror');
  await page.check('#gc-heat'); // a view option travels too
  await page.click('#run');
  await page.waitForSelector('body[data-graphcut-done="true"]', { timeout: 60_000 });
  const original = await canvasPixels(page);

  await page.click('#copy-link');
  await page.waitForFunction(() => /link copied/.test(document.getElementById('share-status').textContent));
  const link = await page.evaluate(() => navigator.clipboard.readText());
  assert.equal(link, page.url(), 'the clipboard holds the page\'s own URL');
  const query = new URL(link).searchParams;
  for (const [key, value] of [['sample', 'tiles_64'], ['method', 'graphcut'], ['seed', '5'], ['w', '64'], ['h', '72'],
    ['gc-refine', '5'], ['gc-blend', 'feather'], ['gc-mirror', '1'], ['gc-rotate', '0'], ['gc-heat', '1'], ['gc-k', '0.01']]) {
    assert.equal(query.get(key), value, `${key} in ${link}`);
  }

  const fresh = await openFresh(link);
  const p = fresh.page;
  assert.equal(await p.getAttribute('body', 'data-exemplar'), 'tiles 64×64');
  assert.equal(await p.getAttribute('button[data-panel="graphcut"]', 'aria-selected'), 'true');
  assert.equal(await p.inputValue('#seed'), '5');
  assert.equal(await p.inputValue('#out-height'), '72');
  assert.equal(await p.inputValue('#gc-refine'), '5');
  assert.equal(await p.inputValue('#gc-blend'), 'feather');
  assert.equal(await p.isChecked('#gc-mirror'), true);
  assert.equal(await p.isChecked('#gc-heat'), true);
  await p.click('#run');
  await p.waitForSelector('body[data-graphcut-done="true"]', { timeout: 60_000 });
  const reproduced = await canvasPixels(p);
  assert.equal(reproduced.length, 64 * 72 * 4);
  assert.deepEqual(reproduced, original, 'the same pixels');
  await p.screenshot({ path: `${RESULTS}/share-reproduced.png` });
  await p.close();
  assert.deepEqual(fresh.errors, []);
  assert.deepEqual(errors, []);
});

test('without a clipboard the link is shown selected', async () => {
  const { page } = demo;
  await page.evaluate(() => {
    Object.defineProperty(navigator, 'clipboard', { value: { writeText: () => Promise.reject(new Error('denied')) } });
  });
  await page.click('#copy-link');
  await page.waitForSelector('#share-link-label:not([hidden])');
  const shown = await page.evaluate(() => {
    const input = document.getElementById('share-link');
    return { value: input.value, focused: document.activeElement === input, selected: input.selectionEnd - input.selectionStart };
  });
  assert.equal(shown.value, page.url());
  assert.ok(shown.focused, 'the link box has focus');
  assert.equal(shown.selected, shown.value.length, 'the whole link is selected');
  assert.match(await page.textContent('#share-status'), /copy the selected link/);
});

test('a design-stage tab and its options come back from the URL; an upload is left out', async () => {
  const base = new URL(demo.page.url());
  const fresh = await openFresh(`${base.origin}/?sample=brick_64&method=design&ds-stages=synthesis&dsy-energy-kind=haar&dsy-compare=1`);
  const p = fresh.page;
  assert.equal(await p.getAttribute('body', 'data-design-stage'), 'synthesis');
  assert.equal(await p.inputValue('#dsy-energy-kind'), 'haar');
  assert.equal(await p.isChecked('#dsy-compare'), true);
  assert.equal(await p.getAttribute('body', 'data-exemplar'), 'brick 64×64');
  assert.match(p.url(), /ds-stages=synthesis/);

  const png = await p.evaluate(async () => Array.from(new Uint8Array(await (await fetch('./samples/tiles_64.png')).arrayBuffer())));
  await p.setInputFiles('#upload', { name: 'mine.png', mimeType: 'image/png', buffer: Buffer.from(png) });
  await p.waitForSelector('body[data-exemplar="mine.png"]');
  await p.waitForFunction(() => !location.search.includes('sample='));
  assert.match(await p.textContent('#share-note'), /uploaded exemplar cannot be in it/);
  await p.close();
  assert.deepEqual(fresh.errors, []);
});
