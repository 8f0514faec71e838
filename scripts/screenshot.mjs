// The README's picture of the page, docs/page.png: the demo in headless Chromium, texture
// optimisation of the tiles sample run to the end, at the window size of a laptop.
//   node scripts/screenshot.mjs [OUT.png]        (needs the package: ./scripts/build.sh)
import { chromium } from 'playwright-core';
import { startServer } from './serve.mjs';

const out = process.argv[2] ?? new URL('../docs/page.png', import.meta.url).pathname;
const server = await startServer({ port: 0 });
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage', '--no-first-run'],
});
try {
  const page = await browser.newPage({ viewport: { width: 1400, height: 860 } });
  await page.goto(`http://127.0.0.1:${server.address().port}/`);
  await page.waitForSelector('body[data-ready="true"]', { timeout: 30_000 });
  await page.click('button[data-panel="optimization"]');
  await page.click('button[data-sample="tiles_64"]');
  await page.waitForSelector('body[data-exemplar="tiles 64×64"]');
  await page.click('#run');
  await page.waitForSelector('body[data-optimization-done="true"]', { timeout: 120_000 });
  await page.waitForTimeout(500);
  await page.screenshot({ path: out });
  console.log(`screenshot: ${out}`);
} finally {
  await browser.close();
  server.close();
}
