// Shared set-up for the browser end-to-end tests: the demo server on a free port and Debian's
// headless Chromium driven by playwright-core (a test tool's own browser download does not work here).
import { mkdirSync } from 'node:fs';
import { chromium } from 'playwright-core';
import { startServer } from '../../scripts/serve.mjs';

export const RESULTS = new URL('../../test-results/', import.meta.url).pathname;

/**
 * The page in headless Chromium, served cross-origin isolated (its worker runs the threaded
 * module) unless `isolated` is false.
 */
export async function openDemo({ isolated = true } = {}) {
  mkdirSync(RESULTS, { recursive: true });
  const server = await startServer({ port: 0, isolated });
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: [
      '--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--no-first-run',
    ],
  });
  const page = await browser.newPage({ viewport: { width: 1400, height: 900 } });
  const errors = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (msg) => msg.type() === 'error' && errors.push(msg.text()));
  const { port } = server.address();
  await page.goto(`http://127.0.0.1:${port}/`);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  return {
    page,
    errors,
    async close() {
      await browser.close();
      server.close();
    },
  };
}

/** The RGBA pixels of the canvas with `id` (default: the output canvas), as a plain array. */
export const canvasPixels = (page, id = 'output-canvas') =>
  page.evaluate((id) => {
    const c = document.getElementById(id);
    return Array.from(c.getContext('2d').getImageData(0, 0, c.width, c.height).data);
  }, id);

/**
 * Opens the panel `panel` with the built-in sample `sample` (e.g. 'gravel_64') and, given
 * `size`, a `size` x `size` output (or `[width, height]`): the set-up most page tests start from.
 */
export async function openPanel(page, panel, sample, size) {
  await page.click(`button[data-panel="${panel}"]`);
  await page.click(`button[data-sample="${sample}"]`);
  const [name, side] = sample.split('_');
  await page.waitForSelector(`body[data-exemplar="${name} ${side}×${side}"]`);
  if (size) {
    const [width, height] = Array.isArray(size) ? size : [size, size];
    await page.fill('#out-width', String(width));
    await page.fill('#out-height', String(height));
    await page.dispatchEvent('#out-height', 'change');
  }
}

/**
 * The soft-constraint demo's start: texture optimisation of tiles 64x64 to 96x96 run to done on
 * its panel. Returns `redness()`: the mean red minus green over the middle band (rows 40-55,
 * columns 20-75) that the demo's strokes cover, to see the synthesis follow red paint.
 */
export async function finishedOptimizationForPaint(page) {
  await openPanel(page, 'optimization', 'tiles_64', 96);
  await page.click('#run');
  await page.waitForSelector('body[data-optimization-done="true"]', { timeout: 60_000 });
  return async () => {
    const px = await canvasPixels(page, 'output-canvas');
    let sum = 0;
    for (let y = 40; y < 56; y++) for (let x = 20; x < 76; x++) sum += px[(y * 96 + x) * 4] - px[(y * 96 + x) * 4 + 1];
    return sum / (16 * 56);
  };
}

/**
 * Quality figures `{ coherence, completeness, histogram }` against the sample texture `sample`
 * (e.g. 'tiles_64'), measured in the page by the same wasm build the page uses, of a `width` x
 * `height` image: `pixels` (RGBA, as `canvasPixels` returns them), or, to give assertions a
 * bound that a bad output would cross, 'noise' (uniform, fixed seed) or 'flat' (the sample's
 * mean colour everywhere).
 */
export const qualityInPage = (page, sample, pixels, width, height) =>
  page.evaluate(async ({ sample, pixels, width, height }) => {
    const wasm = await import('/pkg/texsynth.js');
    const bytes = new Uint8Array(await (await fetch(`./samples/${sample}.png`)).arrayBuffer());
    const exemplar = wasm.Exemplar.fromBytes(bytes);
    const rgba = new Uint8ClampedArray(width * height * 4);
    if (pixels === 'noise') {
      let state = 12345;
      for (let i = 0; i < rgba.length; i++) {
        state = (Math.imul(state, 1103515245) + 12345) >>> 0;
        rgba[i] = i % 4 === 3 ? 255 : state >>> 24;
      }
    } else if (pixels === 'flat') {
      const own = exemplar.toRgba();
      const mean = [0, 1, 2, 3].map((c) => {
        let sum = 0;
        for (let i = c; i < own.length; i += 4) sum += own[i];
        return Math.round(sum / (own.length / 4));
      });
      for (let i = 0; i < rgba.length; i++) rgba[i] = mean[i % 4];
    } else {
      rgba.set(pixels);
    }
    const q = wasm.measureQuality(exemplar, rgba, width, height);
    exemplar.free();
    return { coherence: q.coherence, completeness: q.completeness, histogram: q.histogram, flat: q.flat };
  }, { sample, pixels, width, height });

/** Presses Tab till the focused element matches `selector`; returns the presses it took (at
 * most `limit`). */
export async function tabTo(page, selector, limit = 60) {
  for (let n = 0; n < limit; n++) {
    if (await page.evaluate((s) => document.activeElement?.matches(s), selector)) return n;
    await page.keyboard.press('Tab');
  }
  throw new Error(`Tab never reached ${selector}`);
}
