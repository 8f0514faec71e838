// The page's worker on the threaded module: served cross-origin isolated, the page says how many
// threads each synthesis uses and makes the same pixels as a page served without isolation, which
// runs single-threaded and says why. A build without the threaded module (no nightly) runs
// single-threaded on both and says so.
import { existsSync } from 'node:fs';
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { canvasPixels, openDemo, openPanel, RESULTS } from './harness.mjs';

const built = existsSync(new URL('../../site/pkg/threads/texsynth_bg.wasm', import.meta.url));
const demos = [];
after(async () => Promise.all(demos.map((demo) => demo.close())));

/** Opens the page, runs graph cut (entire patch) and texture optimisation, returns what it saw. */
async function runOn(isolated) {
  const demo = await openDemo({ isolated });
  demos.push(demo);
  const { page, errors } = demo;
  await page.waitForSelector('#version[data-threads]');
  const version = { text: await page.textContent('#version'), title: await page.getAttribute('#version', 'title') };
  const cores = await page.evaluate(() => navigator.hardwareConcurrency);
  await openPanel(page, 'graphcut', 'tiles_64', [192, 160]);
  await page.selectOption('#gc-placement', 'entire-patch');
  await page.dispatchEvent('#gc-placement', 'change');
  await page.click('#run');
  await page.waitForSelector('body[data-graphcut-done="true"]', { timeout: 90_000 });
  await page.uncheck('#gc-seams');
  const graphcut = await canvasPixels(page);
  await openPanel(page, 'optimization', 'gravel_64', 96);
  await page.click('#run');
  await page.waitForSelector('body[data-optimization-done="true"]', { timeout: 90_000 });
  const optimization = await canvasPixels(page);
  await page.screenshot({ path: `${RESULTS}/threads-${isolated ? 'isolated' : 'not-isolated'}.png`, fullPage: true });
  return { version, cores, graphcut, optimization, errors };
}

test('an isolated page runs the threaded module and makes the single-threaded pixels', async () => {
  const threaded = await runOn(true);
  const single = await runOn(false);
  if (built) {
    assert.match(threaded.version.text, new RegExp(`· ${threaded.cores} threads?$`));
    assert.match(threaded.version.title, /pool of threads/);
  } else {
    assert.match(threaded.version.text, /· single-threaded$/);
    assert.match(threaded.version.title, /the threaded module did not load/);
  }
  assert.match(single.version.text, /· single-threaded$/);
  assert.match(single.version.title, /not cross-origin isolated.*Cross-Origin-Embedder-Policy: require-corp/);
  assert.equal(threaded.graphcut.length, 192 * 160 * 4);
  assert.ok(threaded.graphcut.some((v, i) => i % 4 !== 3 && v !== threaded.graphcut[0]), 'graph cut drew a texture');
  assert.deepEqual(threaded.graphcut, single.graphcut, 'graph cut: same pixels at any thread count');
  assert.deepEqual(threaded.optimization, single.optimization, 'texture optimisation: same pixels at any thread count');
  assert.deepEqual(threaded.errors, []);
  assert.deepEqual(single.errors, []);
});
