// Shared set-up for the browser end-to-end tests: the demo server on a free port and Debian's
// headless Chromium driven by playwright-core (a test tool's own browser download does not work here).
import { mkdirSync } from 'node:fs';
import { chromium } from 'playwright-core';
import { startServer } from '../../scripts/serve.mjs';

export const RESULTS = new URL('../../test-results/', import.meta.url).pathname;

export async function openDemo() {
  mkdirSync(RESULTS, { recursive: true });
  const server = await startServer({ port: 0 });
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
