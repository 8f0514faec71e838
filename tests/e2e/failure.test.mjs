// Failure is visible on the page and leaves it usable: uploads that are empty, cut
// short or lie about their size each show the library's readable message and keep the exemplar;
// a session the worker refuses (a 1x1 exemplar) shows its message; then a good upload works,
// the message goes away, and no uncaught error reached the console.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { openDemo } from './harness.mjs';

let demo;
let goodPng;
before(async () => {
  demo = await openDemo();
  goodPng = Buffer.from(await demo.page.evaluate(async () =>
    Array.from(new Uint8Array(await (await fetch('./samples/tiles_64.png')).arrayBuffer()))));
});
after(async () => demo?.close());

const upload = (page, name, buffer) => page.setInputFiles('#upload', { name, mimeType: 'image/png', buffer });
const errorText = async (page) => {
  await page.waitForSelector('#error:not([hidden])');
  return page.textContent('#error');
};

/** The good PNG with its header's width and height replaced by `w` x `h`. */
const lying = (w, h) => {
  const bytes = Buffer.from(goodPng);
  bytes.writeUInt32BE(w, 16);
  bytes.writeUInt32BE(h, 20);
  return bytes;
};

test('bad uploads show a readable message and keep the exemplar', async () => {
  const { page } = demo;
  const before = await page.textContent('#exemplar-info');
  const cases = [
    ['empty.png', Buffer.alloc(0), /empty\.png: empty input/],
    ['cut.png', goodPng.subarray(0, goodPng.length >> 1), /cut\.png: could not decode the image/],
    ['liar.png', lying(100000, 100000), /liar\.png: .*(100000|could not decode)/],
    ['text.png', Buffer.from('<html>not an image</html>'), /text\.png: could not decode the image/],
  ];
  for (const [name, bytes, message] of cases) {
    await page.evaluate(() => { document.getElementById('error').hidden = true; });
    await upload(page, name, bytes);
    assert.match(await errorText(page), message);
    assert.equal(await page.textContent('#exemplar-info'), before, `${name} keeps the exemplar`);
  }
});

test('a 1x1 upload decodes, and the session the worker refuses for it shows its message', async () => {
  const { page } = demo;
  await page.evaluate(() => { document.getElementById('error').hidden = true; });
  const onePixel = Buffer.from(await page.evaluate(async () => {
    const canvas = new OffscreenCanvas(1, 1);
    canvas.getContext('2d').fillRect(0, 0, 1, 1);
    return Array.from(new Uint8Array(await (await canvas.convertToBlob({ type: 'image/png' })).arrayBuffer()));
  }));
  await upload(page, 'dot.png', onePixel);
  await page.waitForSelector('body[data-exemplar="dot.png"]');
  await page.click('#step');
  assert.match(await errorText(page), /exemplar|neighbourhood|1x1/);
});

test('after the failures a good upload works and nothing uncaught was logged', async () => {
  const { page, errors } = demo;
  await upload(page, 'good.png', goodPng);
  await page.waitForSelector('body[data-exemplar="good.png"]');
  assert.equal(await page.isHidden('#error'), true);
  await page.click('#step');
  await page.waitForSelector('body[data-iterations="1"]', { timeout: 30_000 });
  assert.match(await page.textContent('#exemplar-info'), /good\.png: 64×64/);
  assert.deepEqual(errors, []);
});
