// The page stays responsive while a 1024x1024 texture optimization and a 1024x1024 graph cut run
// (their sessions live in a Web Worker): a button click is handled within 100 ms during each run,
// and no main-thread task lasts 100 ms or more, the length that would hold a click past that.
// What remains on the main thread per step is drawing: putting a 1024x1024 picture on the canvas,
// keeping it for the history and committing it, 10-20 ms on a quiet machine. A shared two-core
// machine can stretch one such task past the Long Tasks API's 50 ms mark, so the tasks over 50 ms
// are printed as figures rather than refused.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { openDemo, RESULTS } from './harness.mjs';

let demo;
before(async () => {
  demo = await openDemo();
  await demo.page.evaluate(() => {
    window.longTasks = [];
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) window.longTasks.push({ start: entry.startTime, duration: entry.duration });
    }).observe({ type: 'longtask', buffered: false });
    // How long after the input each click waited for the main thread (event.timeStamp is the
    // input's time; the handler runs when the main thread is free).
    window.clickDelays = [];
    document.addEventListener('click', (e) => window.clickDelays.push(performance.now() - e.timeStamp), true);
  });
});
after(async () => demo?.close());

/** Runs the current panel at 1024x1024 for `ms`, clicking Pause and Run once in the middle. */
async function measureRun(page, panel, ms) {
  await page.click(`button[data-panel="${panel}"]`);
  await page.fill('#out-width', '1024');
  await page.fill('#out-height', '1024');
  await page.dispatchEvent('#out-height', 'change');
  const from = await page.evaluate(() => {
    window.clickDelays.length = 0;
    return performance.now();
  });
  await page.click('#run');
  // Wait until the run has made a first step (session construction and one step in the worker).
  await page.waitForFunction((p) => Number(document.body.dataset[p === 'graphcut' ? 'patches' : 'iterations']) > 0, panel, { timeout: 60_000 });
  await page.waitForTimeout(ms / 2);
  const clickStart = Date.now();
  await page.click('#pause');
  const pauseRoundTrip = Date.now() - clickStart;
  await page.click('#run');
  await page.waitForTimeout(ms / 2);
  await page.click('#pause');
  const figures = await page.evaluate((from) => ({
    longTasks: window.longTasks.filter((t) => t.start >= from),
    clickDelays: [...window.clickDelays],
    status: document.getElementById('status').textContent,
    steps: document.body.dataset.patches + '/' + document.body.dataset.iterations,
  }), from);
  await page.screenshot({ path: `${RESULTS}/responsive-${panel}.png`, fullPage: true });
  await page.click('#reset');
  return { ...figures, pauseRoundTrip };
}

test('control: the Long Tasks observer sees an 80 ms busy main thread', async () => {
  const { page } = demo;
  const from = await page.evaluate(() => {
    const start = performance.now();
    setTimeout(() => {
      while (performance.now() - start < 80);
    }, 0);
    return start;
  });
  await page.waitForFunction((from) => window.longTasks.some((t) => t.start >= from && t.duration >= 75), from, { timeout: 5000 });
  await page.evaluate(() => { window.longTasks.length = 0; });
});

for (const panel of ['optimization', 'graphcut']) {
  test(`1024x1024 ${panel}: no main-thread task of 100 ms, clicks handled within 100 ms`, async () => {
    const { page, errors } = demo;
    const figures = await measureRun(page, panel, 6000);
    const longest = Math.max(0, ...figures.longTasks.map((t) => t.duration));
    console.log(`# ${panel} 1024x1024: ${figures.longTasks.length} long tasks, longest ${longest.toFixed(0)} ms; click delays ${figures.clickDelays.map((d) => d.toFixed(1)).join(', ')} ms; pause click round trip ${figures.pauseRoundTrip} ms; steps ${figures.steps}`);
    assert.ok(longest < 100, `a main-thread task took ${longest.toFixed(0)} ms: ${JSON.stringify(figures.longTasks)}`);
    assert.ok(figures.clickDelays.length >= 3, `clicks seen: ${figures.clickDelays.length}`);
    for (const delay of figures.clickDelays) assert.ok(delay < 100, `a click waited ${delay.toFixed(0)} ms`);
    assert.deepEqual(errors, []);
  });
}
