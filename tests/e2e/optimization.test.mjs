// The "Texture optimization" panel in headless Chromium: steps redraw the canvas, Run goes to
// done, the energy plot gets its points, the teaching view draws the offset map.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, openDemo, qualityInPage, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
});
after(async () => demo?.close());

/** Pixels of the plot's line colour (#e0a458), i.e. the energy points and line. */
const plotInk = (page) =>
  page.evaluate(() => {
    const c = document.getElementById('to-energy');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - 224) < 12 && Math.abs(d[i + 1] - 164) < 12 && Math.abs(d[i + 2] - 88) < 12) n++;
    return n;
  });

test('stepping redraws, running reaches done, the plot has points', async () => {
  const { page, errors } = demo;
  await page.click('button[data-sample="tiles_64"]');
  await page.waitForSelector('body[data-exemplar="tiles 64×64"]');
  await page.fill('#out-width', '128');
  await page.fill('#out-height', '128');
  await page.dispatchEvent('#out-height', 'change');
  await page.click('#step');
  await page.waitForSelector('body[data-iterations="1"]');
  const first = await canvasPixels(page, 'output-canvas');
  assert.equal(first.length, 128 * 128 * 4);
  await page.click('#step');
  await page.waitForSelector('body[data-iterations="2"]');
  const second = await canvasPixels(page, 'output-canvas');
  assert.notDeepEqual(first, second, 'the canvas changes between iterations');
  assert.match(await page.textContent('#to-readout'), /level 1\/\d+ · resolution 1\/\d+ · neighbourhood 8×8 · iteration 2/);

  await page.click('#run');
  await page.waitForSelector('body[data-optimization-done="true"]', { timeout: 60_000 });
  assert.equal(await page.textContent('#status'), 'done');
  const iterations = Number(await page.getAttribute('body', 'data-iterations'));
  assert.ok(iterations >= 4, `${iterations} iterations`);
  assert.ok((await plotInk(page)) > 20 * 2, 'the energy plot shows its points');
  const final = await canvasPixels(page, 'output-canvas');
  assert.ok(new Set(final).size > 50, 'the output is a texture, not a flat colour');
  assert.match(await page.textContent('#to-quality'), /coherence .* completeness .* histogram/);
  // Against bad outputs scored the same way. Coherence: far below noise's (about 0.0008 against
  // 0.08); a flat image scores 0.001, so coherence alone cannot tell a washed-out output.
  // Completeness can: a flat image scores 0.011, the output about 0.0002.
  const coherence = Number(await page.getAttribute('#to-quality', 'data-coherence'));
  const noise = await qualityInPage(page, 'tiles_64', 'noise', 128, 128);
  const flat = await qualityInPage(page, 'tiles_64', 'flat', 128, 128);
  const output = await qualityInPage(page, 'tiles_64', final, 128, 128);
  assert.ok(coherence < noise.coherence / 10, `coherence ${coherence}, noise ${noise.coherence}`);
  assert.ok(
    output.completeness < flat.completeness / 10,
    `completeness ${output.completeness}, flat ${flat.completeness}`,
  );
  // The detail metric in the readout: a flat image scores 1, the exemplar itself about 0.10.
  assert.match(await page.textContent('#to-quality'), /flat \d+\.\d% \(the exemplar itself: about 10%\)/);
  const detail = Number(await page.getAttribute('#to-quality', 'data-flat'));
  assert.equal(flat.flat, 1);
  assert.ok(detail < 0.25, `flat fraction ${detail}`);
  await page.screenshot({ path: `${RESULTS}/optimization.png`, fullPage: true });

  await page.check('#to-teaching');
  const teaching = await canvasPixels(page, 'output-canvas');
  assert.notDeepEqual(teaching, final, 'the teaching view draws the offset map');
  await page.screenshot({ path: `${RESULTS}/optimization-teaching.png`, fullPage: true });
  assert.deepEqual(errors, []);
});

test('reset clears the run and a bad option shows an error', async () => {
  const { page } = demo;
  await page.click('#reset');
  assert.equal(await page.getAttribute('body', 'data-iterations'), '0');
  await page.fill('#to-r', '5');
  await page.dispatchEvent('#to-r', 'change');
  await page.click('#step');
  await page.waitForSelector('#error:not([hidden])');
  assert.match(await page.textContent('#error'), /invalid r: must be in \(0, 2\], got 5/);
  // The M-step's own gradient weight reaches the session: out of range, it names itself.
  await page.fill('#to-r', '0.8');
  await page.dispatchEvent('#to-r', 'change');
  await page.fill('#to-m-step-mu', '-1');
  await page.dispatchEvent('#to-m-step-mu', 'change');
  await page.click('#step');
  await page.waitForFunction(() => /invalid mStepMu/.test(document.getElementById('error').textContent));
  await page.fill('#to-m-step-mu', '');
  await page.dispatchEvent('#to-m-step-mu', 'change');
});

test('a large output splits iterations into parts the readout names', async () => {
  const { page, errors } = demo;
  // A fresh page: the test before leaves a bad option in the form, and in the URL (which a
  // reload would restore), so the bare address.
  await page.goto(new URL('/', page.url()).href);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  await page.click('button[data-sample="tiles_128"]');
  await page.waitForSelector('body[data-exemplar="tiles 128×128"]');
  await page.fill('#out-width', '1024');
  await page.fill('#out-height', '1024');
  await page.dispatchEvent('#out-height', 'change');
  // At 1024x1024 the graph-cut start of the coarsest level (256x256) takes longer than a step's
  // 60 ms, and so do iterations from the second level on.
  const readouts = [];
  let n = 0;
  const stepOnce = async () => {
    n += 1;
    await page.click('#step');
    await page.waitForSelector(`body[data-steps="${n}"]`, { timeout: 30_000 });
    if (await page.getAttribute('body', 'data-step-kind') === 'part') readouts.push(await page.textContent('#to-readout'));
  };
  await stepOnce();
  assert.equal(readouts.length, 1, 'the first step stops inside the graph-cut start');
  assert.match(readouts[0], /\(making the graph-cut start of the coarsest level\)/);
  while (n < 120 && !readouts.some((r) => /% of the iteration/.test(r))) await stepOnce();
  assert.match(
    readouts.at(-1),
    /iteration \d+ \((first M-step|E-step|M-step), \d+% of the iteration\)/,
  );
  await page.screenshot({ path: `${RESULTS}optimization-part-1024.png` });
  assert.deepEqual(errors, []);
});
