// The large-upload prompt (www/lib/large-upload.js): an upload above the working size asks first
// (shrink, crop a square, use it whole, or cancel); a small upload and the samples do not.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { openDemo, RESULTS } from './harness.mjs';

let demo;
let bigPng;
let smallPng;

before(async () => {
  demo = await openDemo();
  const { page } = demo;
  // A 1200x900 photo stand-in made by the browser's own PNG encoder: smooth gradients (so the
  // file stays small) under a grid of discs whose colours vary, so regions differ from one another.
  const base64 = await page.evaluate(async () => {
    const canvas = new OffscreenCanvas(1200, 900);
    const ctx = canvas.getContext('2d');
    const gradient = ctx.createLinearGradient(0, 0, 1200, 900);
    gradient.addColorStop(0, '#2a6f97');
    gradient.addColorStop(1, '#e9c46a');
    ctx.fillStyle = gradient;
    ctx.fillRect(0, 0, 1200, 900);
    for (let y = 0; y < 900; y += 50) {
      for (let x = 0; x < 1200; x += 50) {
        ctx.fillStyle = `hsl(${(x * 7 + y * 3) % 360} 60% 45%)`;
        ctx.beginPath();
        ctx.arc(x + 25, y + 25, 10 + ((x + y) % 13), 0, 2 * Math.PI);
        ctx.fill();
      }
    }
    const blob = await canvas.convertToBlob({ type: 'image/png' });
    const bytes = new Uint8Array(await blob.arrayBuffer());
    let text = '';
    for (const b of bytes) text += String.fromCharCode(b);
    return btoa(text);
  });
  bigPng = Buffer.from(base64, 'base64');
  smallPng = Buffer.from(await page.evaluate(async () =>
    Array.from(new Uint8Array(await (await fetch('./samples/tiles_64.png')).arrayBuffer()))));
});
after(async () => demo?.close());

const upload = (page, name, buffer) => page.setInputFiles('#upload', { name, mimeType: 'image/png', buffer });
const exemplarSize = (page) => page.evaluate(() => document.body.dataset.exemplarSize);
const exemplarLabel = (page) => page.evaluate(() => document.body.dataset.exemplar);
const dialogOpen = (page) => page.evaluate(() => document.getElementById('large-upload').open);
// The visible button of that choice (Cancel is in both views).
const choice = (name) => `#large-upload button[data-choice="${name}"]:visible`;

async function uploadBig(page, name = 'big.png') {
  await upload(page, name, bigPng);
  await page.waitForSelector('#large-upload[open]');
}

test('a large upload asks first, naming its size; Shrink gives the working size', async () => {
  const { page, errors } = demo;
  assert.equal(await page.inputValue('#working-size'), '512');
  await uploadBig(page);
  const message = await page.textContent('#large-upload-message');
  assert.match(message, /big\.png is 1200×900; the working size is 512\./);
  assert.match(message, /graph cut/);
  // The previous exemplar stays until a choice is made; the first choice has the focus.
  assert.equal(await exemplarLabel(page), 'tiles 128×128');
  assert.equal(await page.evaluate(() => document.activeElement.dataset.choice), 'shrink');
  assert.equal(await page.textContent(choice('shrink')), 'Shrink to 512 (512×384)');
  await page.screenshot({ path: `${RESULTS}/large-upload-prompt.png` });
  await page.click(choice('shrink'));
  await page.waitForSelector('body[data-exemplar="big.png, shrunk"]');
  assert.equal(await exemplarSize(page), '512x384');
  assert.equal(await dialogOpen(page), false);
  assert.match(await page.textContent('#exemplar-info'), /512×384/);
  assert.deepEqual(errors, []);
});

test('Escape keeps the previous exemplar', async () => {
  const { page, errors } = demo;
  await uploadBig(page, 'other.png');
  await page.keyboard.press('Escape');
  await page.waitForFunction(() => !document.getElementById('large-upload').open);
  assert.equal(await exemplarLabel(page), 'big.png, shrunk');
  assert.equal(await exemplarSize(page), '512x384');
  // Cancel in the crop view does the same.
  await uploadBig(page, 'other.png');
  await page.click(choice('crop'));
  await page.click(choice('cancel'));
  assert.equal(await dialogOpen(page), false);
  assert.equal(await exemplarLabel(page), 'big.png, shrunk');
  assert.deepEqual(errors, []);
});

test('a keyboard-driven crop gives the chosen square, with the photo\'s own pixels', async () => {
  const { page, errors } = demo;
  await uploadBig(page);
  await page.click(choice('crop'));
  await page.waitForSelector('#large-upload [data-part="crop-view"]:not([hidden])');
  assert.equal(await page.evaluate(() => document.activeElement.dataset.part), 'crop-canvas');
  assert.equal(await page.isVisible('#large-upload [data-choice="shrink"]'), false, 'the choices give way to the crop view');
  // The default square: min(working size, shorter side), centred.
  assert.match(await page.textContent('#large-upload-crop-readout'), /^Square 512×512 px at \(344, 194\) of 1200×900$/);
  await page.screenshot({ path: `${RESULTS}/large-upload-crop.png` });
  // - shrinks by 32 (a 900-pixel side's step) around the centre; an arrow moves by 12 (1% of 1200).
  for (const key of ['-', '-', 'ArrowRight', 'ArrowRight', 'ArrowDown']) await page.keyboard.press(key);
  assert.match(await page.textContent('#large-upload-crop-readout'), /^Square 448×448 px at \(400, 238\)/);
  await page.keyboard.press('Enter');
  await page.waitForSelector('body[data-exemplar="big.png, crop 448×448 at (400, 238)"]');
  assert.equal(await exemplarSize(page), '448x448');
  // Oracle: the browser's PNG decoder, the same square cut out of the upload.
  const max = await page.evaluate(async ({ base64, x, y, side }) => {
    const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
    const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
    const ref = new OffscreenCanvas(side, side);
    ref.getContext('2d').drawImage(bitmap, -x, -y);
    const want = ref.getContext('2d').getImageData(0, 0, side, side).data;
    const shown = document.getElementById('exemplar-canvas');
    const got = shown.getContext('2d').getImageData(0, 0, shown.width, shown.height).data;
    let max = 0;
    for (let i = 0; i < want.length; i++) max = Math.max(max, Math.abs(want[i] - got[i]));
    return max;
  }, { base64: bigPng.toString('base64'), x: 400, y: 238, side: 448 });
  assert.ok(max <= 1, `largest channel difference ${max}`);
  // The page goes on working with it: one optimization step.
  await page.click('#step');
  await page.waitForFunction(() => Number(document.body.dataset.iterations) > 0, null, { timeout: 120_000 });
  assert.deepEqual(errors, []);
});

test('the pointer moves and draws the square; a crop above the working size is shrunk to it', async () => {
  const { page, errors } = demo;
  await page.selectOption('#working-size', '256');
  await uploadBig(page);
  assert.match(await page.textContent('#large-upload-message'), /the working size is 256\./);
  await page.click(choice('crop'));
  const crop = () => page.evaluate(() => document.getElementById('large-upload').dataset.crop.split(',').map(Number));
  assert.deepEqual(await crop(), [472, 322, 256]);
  const box = await page.locator('#large-upload [data-part="crop-canvas"]').boundingBox();
  const scale = 1200 / box.width;
  // Drag from the square's centre 60 CSS pixels right: the square follows.
  const cx = box.x + 600 / scale;
  const cy = box.y + 450 / scale;
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  await page.mouse.move(cx + 30, cy, { steps: 3 });
  await page.mouse.move(cx + 60, cy, { steps: 3 });
  await page.mouse.up();
  const [x1, y1] = await crop();
  assert.ok(Math.abs(x1 - (472 + 60 * scale)) <= 2, `moved to ${x1}`);
  assert.equal(y1, 322);
  // Drag outside the square from near the top-left corner: a new square from that corner.
  const from = { x: box.x + 20 / scale, y: box.y + 30 / scale };
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(from.x + 200 / scale, from.y + 150 / scale, { steps: 4 });
  await page.mouse.move(from.x + 400 / scale, from.y + 300 / scale, { steps: 4 });
  await page.mouse.up();
  const [x2, y2, side2] = await crop();
  assert.ok(Math.abs(x2 - 20) <= 2 && Math.abs(y2 - 30) <= 2, `drawn at ${x2}, ${y2}`);
  assert.ok(Math.abs(side2 - 400) <= 3, `drawn side ${side2}`);
  // Keyboard again from here: + grows it by 32 around its centre.
  await page.focus('#large-upload [data-part="crop-canvas"]');
  await page.keyboard.press('+');
  assert.equal((await crop())[2], side2 + 32);
  assert.match(await page.textContent('#large-upload-crop-readout'), /shrunk to 256×256 on use/);
  await page.click(choice('accept'));
  await page.waitForFunction(() => document.body.dataset.exemplar.includes(', crop '));
  assert.equal(await exemplarSize(page), '256x256');
  assert.match(await exemplarLabel(page), new RegExp(`crop ${side2 + 32}×${side2 + 32} at`));
  assert.deepEqual(errors, []);
});

test('Use it whole keeps 1200x900; a small upload and a sample show no prompt', async () => {
  const { page, errors } = demo;
  await page.selectOption('#working-size', '512');
  await uploadBig(page, 'whole.png');
  await page.click(choice('whole'));
  await page.waitForSelector('body[data-exemplar="whole.png"]');
  assert.equal(await exemplarSize(page), '1200x900');
  await upload(page, 'small.png', smallPng);
  await page.waitForSelector('body[data-exemplar="small.png"]');
  assert.equal(await dialogOpen(page), false);
  assert.equal(await exemplarSize(page), '64x64');
  // 1024: the same 1200x900 upload is still above it.
  await page.selectOption('#working-size', '1024');
  await uploadBig(page, 'again.png');
  assert.match(await page.textContent(choice('shrink')), /Shrink to 1024 \(1024×768\)/);
  await page.click(choice('cancel'));
  assert.equal(await exemplarLabel(page), 'small.png');
  await page.click('button[data-sample="brick_128"]');
  await page.waitForSelector('body[data-exemplar="brick 128×128"]');
  assert.equal(await dialogOpen(page), false);
  await page.selectOption('#working-size', '512');
  assert.deepEqual(errors, []);
});

/** Checks `times` times, `pause` ms apart, that the page answers a call within a second. */
async function answersMeanwhile(page, times, pause) {
  for (let i = 0; i < times; i++) {
    const started = Date.now();
    await page.evaluate(() => 1);
    assert.ok(Date.now() - started < 1000, `the page answered in ${Date.now() - started} ms`);
    await page.waitForTimeout(pause);
  }
}

test('a photo used whole synthesises, and the quality line says why it is not measured', async () => {
  const { page, errors } = demo;
  // 4000x3000, the size of a phone photo: its patch index alone would pass the memory budget.
  // Flat tiles of colour, so that the PNG stays small (a gradient made 11 MB).
  const photo = Buffer.from(await page.evaluate(async () => {
    const canvas = new OffscreenCanvas(4000, 3000);
    const ctx = canvas.getContext('2d');
    for (let y = 0; y < 3000; y += 250) {
      for (let x = 0; x < 4000; x += 250) {
        ctx.fillStyle = `hsl(${(x / 10 + y / 7) % 360} 50% 45%)`;
        ctx.fillRect(x, y, 250, 250);
      }
    }
    const bytes = new Uint8Array(await (await canvas.convertToBlob({ type: 'image/png' })).arrayBuffer());
    let text = '';
    for (const b of bytes) text += String.fromCharCode(b);
    return btoa(text);
  }), 'base64');
  await page.click('button[data-panel="graphcut"]');
  await page.fill('#out-width', '64');
  await page.fill('#out-height', '64');
  await page.dispatchEvent('#out-height', 'change');
  await upload(page, 'photo.png', photo);
  await page.waitForSelector('#large-upload[open]');
  await page.click(choice('whole'));
  await page.waitForSelector('body[data-exemplar="photo.png"]', { timeout: 60_000 });
  assert.equal(await exemplarSize(page), '4000x3000');
  await page.click('#run');
  await page.waitForSelector('body[data-graphcut-done="true"]', { timeout: 120_000 });
  const quality = await page.textContent('#gc-quality');
  assert.match(quality, /^quality not measured: exemplar 4000x3000: measuring quality needs about 1\.\d GiB .*shrink or crop the exemplar first/);
  assert.equal(await page.getAttribute('#gc-quality', 'data-failed'), 'true');
  await page.screenshot({ path: `${RESULTS}/large-upload-photo-quality.png`, fullPage: true });

  // Feature-guided synthesis: the photo's features are detected in the worker, not on the page
  // (13.5 s there held the page from the panel's first draw on), then drawn, edited and used.
  const started = Date.now();
  await page.click('button[data-panel="features"]');
  await page.evaluate(() => 1);
  assert.ok(Date.now() - started < 3000, `the panel opened in ${Date.now() - started} ms`);
  assert.equal(await page.getAttribute('#fg-exemplar-caption', 'data-detected-here'), 'false');
  assert.match(await page.textContent('#fg-exemplar-caption'), /exemplar 4000×3000: detecting its features in the worker/);
  // The page answers while the worker detects.
  await answersMeanwhile(page, 3, 300);
  await page.waitForSelector('#fg-exemplar-caption[data-map-ready="true"]', { timeout: 120_000 });
  const caption = await page.textContent('#fg-exemplar-caption');
  assert.match(caption, /^exemplar features: \d+ pixels \(the 4000×3000 photo's map, detected and edited in the worker\)$/);
  const before = Number(/(\d+) pixels/.exec(caption)[1]);
  // The view is drawn the size it is shown (140 CSS pixels, not 4000x3000), so the map's
  // one-pixel curves show.
  const view = await page.evaluate(() => [document.getElementById('fg-exemplar').width, document.getElementById('fg-exemplar').height]);
  assert.deepEqual(view, [140, 105]);
  // Paint a curve across the photo in one fast move: the worker's map gains a gapless stroke
  // (about 0.6 of 4000 map pixels), and the view shows it.
  await page.check('input[name="fg-brush"][value="paint"]');
  // The 140x105 view is contained in the 140x140 box: 17.5 pixels above and below it.
  const box = await page.locator('#fg-exemplar').boundingBox();
  const y = box.y + (box.height - 105) / 2 + 105 * 0.37;
  await page.mouse.move(box.x + box.width * 0.2, y);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.8, y, { steps: 2 });
  await page.mouse.up();
  await page.check('input[name="fg-brush"][value="off"]');
  // The keyboard brush ranges over the picture, not the letterbox's bars: at the top of its
  // range the cursor ring sits on the picture's top edge, 17.5 pixels into the box.
  await page.focus('#fg-exemplar');
  for (let n = 0; n < 30; n++) await page.keyboard.press('ArrowUp');
  const ring = await page.evaluate(() => {
    const r = document.querySelector('.brush-ring');
    return [parseFloat(r.style.left), parseFloat(r.style.top)];
  });
  const boxNow = await page.locator('#fg-exemplar').boundingBox();
  assert.ok(Math.abs(ring[1] - (boxNow.y + (boxNow.height - 105) / 2)) < 0.5, `ring at ${ring}, box ${JSON.stringify(boxNow)}`);
  assert.ok(Math.abs(ring[0] - (boxNow.x + boxNow.width / 2)) < 0.5, `ring at ${ring}`);
  await page.focus('#fg-patch');
  await page.waitForFunction((n) => Number(/(\d+) pixels/.exec(document.getElementById('fg-exemplar-caption').textContent)?.[1]) > n + 2000, before, { timeout: 30_000 });
  const painted = await page.evaluate((row) => {
    const canvas = document.getElementById('fg-exemplar');
    const data = canvas.getContext('2d').getImageData(0, row, canvas.width, 1).data;
    // The four orientation-bucket colours of the feature views.
    const buckets = ['255,90,80', '250,210,70', '90,200,255', '170,120,255'];
    let shown = 0;
    for (let i = 0; i < data.length; i += 4) if (buckets.includes(`${data[i]},${data[i + 1]},${data[i + 2]}`)) shown++;
    return shown;
  }, Math.floor(105 * 0.37));
  assert.ok(painted > 70, `the painted curve shows in the view's row: ${painted} of 140 pixels`);
  await page.fill('#fg-patch', '32');
  await page.click('#run');
  // The page answers while the worker synthesises.
  await answersMeanwhile(page, 4, 500);
  await page.waitForSelector('body[data-features-done="true"]', { timeout: 180_000 });
  assert.ok(Number(await page.getAttribute('body', 'data-feature-patches')) >= 1);
  // Both broken-feature counts are measured, against the worker's map of the photo.
  const ours = Number(await page.getAttribute('#fg-quality', 'data-broken') ?? NaN);
  const theirs = Number(await page.getAttribute('#fg-graphcut-caption', 'data-broken') ?? NaN);
  assert.ok(Number.isFinite(ours) && Number.isFinite(theirs), `${ours} ${theirs}`);
  const counts = '-?\\d+\\.\\d, at seams -?\\d+\\.\\d';
  assert.match(await page.textContent('#fg-quality'), new RegExp(`broken features ${counts}$`));
  assert.match(await page.textContent('#fg-graphcut-caption'), new RegExp(`broken features ${counts} \\(feature-guided: ${counts}; lower is better\\)`));
  await page.screenshot({ path: `${RESULTS}/large-upload-photo-features.png`, fullPage: true });
  await page.click('button[data-panel="graphcut"]');
  // Back to the state the next test starts from.
  await page.fill('#out-width', '256');
  await page.fill('#out-height', '256');
  await page.dispatchEvent('#out-height', 'change');
  await page.click('button[data-sample="brick_128"]');
  await page.waitForSelector('body[data-exemplar="brick 128×128"]');
  assert.deepEqual(errors, []);
});

test('a corrupt upload still shows the library\'s message', async () => {
  const { page } = demo;
  await upload(page, 'broken.png', Buffer.concat([bigPng.subarray(0, 8), Buffer.from('truncated')]));
  await page.waitForSelector('#error:not([hidden])');
  assert.match(await page.textContent('#error'), /broken\.png: could not decode the image/);
  assert.equal(await dialogOpen(page), false);
  assert.equal(await exemplarLabel(page), 'brick 128×128');
});

test('on a phone-sized screen the prompt and the crop view fit', async () => {
  const { page, errors } = demo;
  await page.setViewportSize({ width: 390, height: 844 });
  await uploadBig(page, 'phone.png');
  const fits = async (selector) => {
    const box = await page.locator(selector).boundingBox();
    assert.ok(box.x >= 0 && box.x + box.width <= 390 && box.y >= 0 && box.y + box.height <= 844,
      `${selector} at ${JSON.stringify(box)}`);
  };
  await fits('#large-upload');
  for (const name of ['shrink', 'crop', 'whole', 'cancel']) await fits(choice(name));
  await page.screenshot({ path: `${RESULTS}/large-upload-prompt-phone.png` });
  await page.click(choice('crop'));
  await fits('#large-upload');
  await fits('#large-upload [data-part="crop-canvas"]');
  await fits(choice('accept'));
  await page.screenshot({ path: `${RESULTS}/large-upload-crop-phone.png` });
  // Back returns to the choices; Shrink from there.
  await page.click(choice('back'));
  await page.click(choice('shrink'));
  await page.waitForSelector('body[data-exemplar="phone.png, shrunk"]');
  assert.equal(await exemplarSize(page), '512x384');
  await page.setViewportSize({ width: 1400, height: 900 });
  assert.deepEqual(errors, []);
});
