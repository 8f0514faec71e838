// The layout on a 1280x720 projector and on a 390x844 phone: after a short
// run of texture optimization, graph cut and the compare panel, nothing is wider than the
// viewport (document.scrollWidth <= innerWidth), and no console errors. The screenshots
// (test-results/layout-*.png) are for a person to look at.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { openDemo, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
  const { page } = demo;
  await page.click('button[data-sample="tiles_64"]');
  await page.waitForSelector('body[data-exemplar="tiles 64×64"]');
  await page.fill('#out-width', '96');
  await page.fill('#out-height', '96');
  await page.dispatchEvent('#out-height', 'change');
});
after(async () => demo?.close());

const overflow = (page) => page.evaluate(() => ({
  scrollWidth: document.documentElement.scrollWidth,
  innerWidth: window.innerWidth,
  // The widest elements past the right edge, to name the culprit when this fails.
  wide: [...document.querySelectorAll('body *')]
    .filter((el) => el.getBoundingClientRect().right > window.innerWidth + 0.5 && el.getClientRects().length)
    .slice(0, 5).map((el) => `${el.tagName.toLowerCase()}#${el.id}.${el.className}`),
}));

const RUNS = {
  optimization: 'body[data-optimization-done="true"]',
  graphcut: 'body[data-graphcut-done="true"]',
  compare: 'body[data-compare-done="true"]',
};

for (const [panel, done] of Object.entries(RUNS)) {
  test(`${panel}: fits 1280x720 and 390x844`, async () => {
    const { page, errors } = demo;
    await page.setViewportSize({ width: 1280, height: 720 });
    await page.click(`#tab-${panel}`);
    await page.click('#run');
    await page.waitForSelector(done, { timeout: 90_000 });
    for (const [width, height] of [[1280, 720], [390, 844]]) {
      await page.setViewportSize({ width, height });
      await page.waitForTimeout(100);
      const o = await overflow(page);
      assert.ok(o.scrollWidth <= o.innerWidth, `${panel} at ${width}x${height}: scrollWidth ${o.scrollWidth} > ${o.innerWidth}: ${o.wide.join(', ')}`);
      await page.screenshot({ path: `${RESULTS}/layout-${width}-${panel}.png`, fullPage: width < 1000 });
    }
    assert.deepEqual(errors, []);
  });
}

test('every panel (and design stage) fits both sizes before a run', async () => {
  const { page, errors } = demo;
  const tabs = await page.$$eval('#methods [role="tab"]', (t) => t.map((x) => x.dataset.panel));
  const wide = [];
  for (const [width, height] of [[1280, 720], [390, 844]]) {
    await page.setViewportSize({ width, height });
    for (const panel of tabs) {
      await page.click(`#tab-${panel}`);
      const stages = await page.$$eval('#method-options [role="tab"][data-stage]', (t) => t.map((x) => x.dataset.stage));
      for (const stage of stages.length ? stages : [null]) {
        if (stage) await page.click(`#method-options [data-stage="${stage}"]`);
        const o = await overflow(page);
        if (o.scrollWidth > o.innerWidth) wide.push(`${panel}${stage ? `/${stage}` : ''} at ${width}: ${o.scrollWidth} (${o.wide.join(', ')})`);
      }
    }
  }
  assert.deepEqual(wide, []);
  assert.deepEqual(errors, []);
});
