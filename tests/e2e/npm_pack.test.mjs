// The npm package as a user gets it: `npm pack ./pkg`, installed into a fresh project, then used
// in each environment the README describes: Node ESM with no init, the explicit `init()` entry,
// the worker wrapper over worker_threads, the CLI (`npx texsynth-wasm`), TypeScript (`tsc
// --noEmit` on an example that uses every export), and a Vite production build served and
// opened in headless Chromium. The examples are the files of tests/e2e/pack/.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { dirname, extname, join } from 'node:path';
import { chromium } from 'playwright-core';

const ROOT = new URL('../../', import.meta.url).pathname;
const PACK = join(ROOT, 'tests/e2e/pack');
const SAMPLE = join(ROOT, 'www/samples/sand_64.png');
const run = (cmd, args, cwd, options = {}) =>
  execFileSync(cmd, args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'], ...options });
const npm = (args, cwd) => run('npm', args, cwd);

let scratch;
let app;
let packed;

before(() => {
  scratch = mkdtempSync(join(tmpdir(), 'texsynth-pack-'));
  packed = JSON.parse(npm(['pack', join(ROOT, 'pkg'), '--pack-destination', scratch, '--json'], ROOT))[0];
  app = join(scratch, 'app');
  mkdirSync(app);
  writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'scratch', private: true, type: 'module' }));
  npm(['install', '--no-audit', '--no-fund', join(scratch, packed.filename)], app);
  for (const file of readdirSync(PACK)) cpSync(join(PACK, file), join(app, file), { recursive: true });
});

after(() => rmSync(scratch, { recursive: true, force: true }));

test('the tarball holds the generated module, the entry points, types, worker and CLI', () => {
  const files = packed.files.map((f) => f.path).sort();
  const manifest = JSON.parse(readFileSync(join(ROOT, 'pkg.json'), 'utf8'));
  assert.deepEqual(files, [...manifest.files, 'package.json'].sort());
  const wasm = packed.files.find((f) => f.path === 'texsynth_bg.wasm').size;
  console.log(`# package: ${packed.size} bytes packed, ${packed.unpackedSize} unpacked; wasm ${wasm} bytes`);
});

test('Node: import works with no init, sessions iterate, run() is cancelled by an AbortSignal', () => {
  const out = JSON.parse(run('node', ['node-app.mjs', SAMPLE], app));
  const manifest = JSON.parse(readFileSync(join(ROOT, 'pkg.json'), 'utf8'));
  assert.equal(out.version, manifest.version);
  assert.ok(out.steps > 2 && out.done, `steps ${out.steps}`);
  assert.ok(out.coherence > 0 && out.coherence < 0.05, `coherence ${out.coherence}`);
  assert.equal(out.placed, 3);
  assert.equal(out.aborted, 'AbortError');
  assert.equal(out.error, 'empty input: no image bytes were given');
});

test('Node: the explicit init() of texsynth-wasm/web takes a WebAssembly.Module', () => {
  assert.equal(run('node', ['web-app.mjs', SAMPLE], app).trim(), '64');
});

test('Node: the worker wrapper runs a pool, teaching views and a cancelled run on worker_threads', () => {
  const out = JSON.parse(run('node', ['worker-app.mjs', SAMPLE], app));
  assert.deepEqual(out.pool, [[true, 64, 64 * 64 * 4], [true, 64, 64 * 64 * 4]]);
  assert.equal(out.firstImage, 64 * 64 * 4);
  assert.ok(out.levels >= 1);
  assert.equal(out.offsets, 64 * 64 * 4);
  assert.equal(out.aborted, 'AbortError');
  assert.equal(out.finished, true);
});

test('TypeScript: tsc --noEmit on an example using every export (with expected errors) passes', () => {
  run(join(ROOT, 'node_modules/.bin/tsc'), ['-p', 'tsconfig.json'], app);
  // And a wrong type fails: the same example without its @ts-expect-error markers.
  writeFileSync(join(app, 'wrong.ts'), readFileSync(join(app, 'example.ts'), 'utf8').replaceAll('// @ts-expect-error', '//'));
  let failed = '';
  try {
    writeFileSync(join(app, 'tsconfig.wrong.json'), JSON.stringify({ extends: './tsconfig.json', files: ['wrong.ts'] }));
    run(join(ROOT, 'node_modules/.bin/tsc'), ['-p', 'tsconfig.wrong.json'], app);
  } catch (error) {
    failed = error.stdout;
  }
  for (const code of ['TS2561', 'TS2322', 'TS2345']) assert.match(failed, new RegExp(code), failed);
});

test('CLI: synth, synth --jobs, animate, measure, --json, --help, and errors that name the problem', () => {
  // npx once (the bin link); the rest call the same link directly (npx costs about 0.5 s a call).
  assert.match(run('npx', ['--no-install', 'texsynth-wasm', '--help'], app), /synth IN\.png/);
  const cli = (...args) => run(join(app, 'node_modules/.bin/texsynth-wasm'), args, app);
  const synthLog = cli('synth', SAMPLE, '-o', 'out.png', '--method', 'optimization', '--size', '96x96', '--seed', '3', '--tileable', '--set', 'neighbourhoodSizes=[16,8]');
  assert.ok(existsSync(join(app, 'out.png')), synthLog);
  const lines = cli('synth', SAMPLE, '-o', 'gc.png', '--method', 'graphcut', '--size', '64x64', '--json').trim().split('\n').map((l) => JSON.parse(l));
  assert.ok(lines.some((e) => e.kind === 'placed'));
  assert.deepEqual(lines.at(-1), { kind: 'written', path: 'gc.png' });
  cli('synth', SAMPLE, join(ROOT, 'www/samples/gravel_64.png'), '-o', 'jobs-{name}-{seed}.png', '--method', 'graphcut', '--size', '64x64', '--seed', '1,2', '--jobs', '2');
  for (const name of ['sand_64', 'gravel_64']) for (const seed of [1, 2]) assert.ok(existsSync(join(app, `jobs-${name}-${seed}.png`)));
  cli('animate', SAMPLE, '--flow', 'vortex', '--frames', '3', '--size', '48x48', '-o', 'frames');
  assert.deepEqual(readdirSync(join(app, 'frames')).sort(), ['frame-0001.png', 'frame-0002.png', 'frame-0003.png']);
  const measured = JSON.parse(cli('measure', SAMPLE, 'out.png', '--json'));
  assert.ok(measured.coherence < 0.05 && measured.flat < 0.5, JSON.stringify(measured));
  assert.match(cli('measure', SAMPLE, 'out.png'), /^coherence\s+\S+\ncompleteness/);

  const failing = (args, pattern) => {
    try {
      cli(...args);
    } catch (error) {
      assert.ok(error.status > 0);
      assert.match(error.stderr, pattern);
      return;
    }
    assert.fail(`texsynth-wasm ${args.join(' ')} should fail`);
  };
  failing(['synth', 'missing.png', '-o', 'x.png'], /missing\.png: no such file/);
  failing(['synth', 'package.json', '-o', 'x.png'], /package\.json: could not decode/);
  failing(['synth', SAMPLE, '-o', 'x.png', '--set', 'bogus=1'], /unknown option 'bogus'/);
  failing(['synth', SAMPLE, '-o', 'x.png', '--size', 'big'], /--size must be WIDTHxHEIGHT/);
  failing(['frobnicate'], /unknown command 'frobnicate'/);
});

const TYPES = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.png': 'image/png' };

/** A plain static server over `dir` (index.html at /), closed by the returned function. */
async function serveStatic(dir) {
  const server = createServer((req, res) => {
    const path = join(dir, req.url === '/' ? 'index.html' : decodeURIComponent(req.url.split('?')[0]));
    try {
      const body = readFileSync(path);
      res.writeHead(200, { 'content-type': TYPES[extname(path)] ?? 'application/octet-stream' });
      res.end(body);
    } catch {
      res.writeHead(404);
      res.end();
    }
  });
  await new Promise((r) => server.listen(0, '127.0.0.1', r));
  return { url: `http://127.0.0.1:${server.address().port}/`, close: () => server.close() };
}

const launch = () => chromium.launch({
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'],
});

test('Vite: a production build of an app that imports the package runs in headless Chromium', async () => {
  const viteApp = join(app, 'vite-app');
  cpSync(SAMPLE, join(viteApp, 'sand_64.png'));
  run('node', [join(ROOT, 'node_modules/vite/bin/vite.js'), 'build', '--logLevel', 'warn'], viteApp, { env: { ...process.env, NODE_PATH: '' } });
  const dist = join(viteApp, 'dist');
  const assets = readdirSync(join(dist, 'assets'));
  assert.ok(assets.some((f) => f.endsWith('.wasm')), `no .wasm asset in ${assets}`);
  const server = await serveStatic(dist);
  const browser = await launch();
  try {
    const page = await browser.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(server.url);
    await page.waitForSelector('body[data-result]', { timeout: 30_000 }).catch(() => assert.fail(errors.join('\n') || 'no result'));
    const result = JSON.parse(await page.evaluate(() => document.body.dataset.result));
    assert.deepEqual(result, { version: JSON.parse(readFileSync(join(ROOT, 'pkg.json'), 'utf8')).version, done: true, alpha: 255, workerDone: true });
    assert.deepEqual(errors, []);
  } finally {
    await browser.close();
    server.close();
  }
});

// The README's quick starts, as written there: each block follows a `<!-- quickstart: FILE -->`
// line and is run from the installed tarball with a sample exemplar as `sample.png`.
const quickStarts = () => {
  const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');
  const blocks = {};
  for (const [, file, code] of readme.matchAll(/<!-- quickstart: (\S+) -->\n```\w*\n([\s\S]*?)```/g)) blocks[file] = code;
  return blocks;
};

/** The README's `file` written into a fresh folder of the scratch app, with `sample.png` beside it. */
function quickStart(file) {
  const code = quickStarts()[file];
  assert.ok(code, `the README has a quick start ${file}`);
  const dir = join(app, 'readme', file.replace(/[/.]/g, '-'));
  mkdirSync(join(dir, dirname(file)), { recursive: true });
  writeFileSync(join(dir, file), code);
  cpSync(SAMPLE, join(dir, dirname(file), 'sample.png'));
  return dir;
}

/** Whether the canvas of the page at `url` is drawn, opaque, at its centre within a minute. */
async function pageDraws(url) {
  const browser = await launch();
  try {
    const page = await browser.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(url);
    await page.waitForFunction(() => {
      const c = document.querySelector('canvas');
      return c.getContext('2d').getImageData(c.width / 2, c.height / 2, 1, 1).data[3] === 255;
    }, null, { timeout: 60_000 }).catch(() => assert.fail(errors.join('\n') || 'the canvas stayed empty'));
    assert.deepEqual(errors, []);
  } finally {
    await browser.close();
  }
}

test('README: every environment has its quick start', () => {
  assert.deepEqual(Object.keys(quickStarts()).sort(), ['cli.sh', 'node.mjs', 'page.html', 'vite/main.js', 'worker.mjs']);
});

test('README quick start: Node writes its texture', () => {
  const dir = quickStart('node.mjs');
  const log = run('node', ['node.mjs'], dir);
  assert.match(log, /^level 0 /m);
  assert.ok(readFileSync(join(dir, 'out.png')).length > 1000);
});

test('README quick start: Workers run a session and a pool', () => {
  const dir = quickStart('worker.mjs');
  const log = run('node', ['worker.mjs'], dir);
  assert.match(log, /^placed \d+$/m);
  assert.match(log.trim().split('\n').at(-1), /\[ 96, 96 \]/);
});

test('README quick start: the command line makes, tiles, animates and measures', () => {
  const dir = quickStart('cli.sh');
  run('bash', ['-e', 'cli.sh'], dir);
  for (const file of ['out.png', 'tile.png', 'frames/frame-0003.png']) assert.ok(existsSync(join(dir, file)), file);
});

test('README quick start: a page without a bundler draws the texture', async () => {
  const dir = quickStart('page.html');
  cpSync(join(app, 'node_modules/texsynth-wasm'), join(dir, 'node_modules/texsynth-wasm'), { recursive: true });
  const server = await serveStatic(dir);
  try {
    await pageDraws(`${server.url}page.html`);
  } finally {
    server.close();
  }
});

test('README quick start: the Vite build draws the texture', async () => {
  const dir = quickStart('vite/main.js');
  writeFileSync(join(dir, 'vite/index.html'), '<!doctype html><canvas width="128" height="128"></canvas><script type="module" src="./main.js"></script>');
  run('node', [join(ROOT, 'node_modules/vite/bin/vite.js'), 'build', '--logLevel', 'warn'], join(dir, 'vite'), { env: { ...process.env, NODE_PATH: '' } });
  const server = await serveStatic(join(dir, 'vite/dist'));
  try {
    await pageDraws(server.url);
  } finally {
    server.close();
  }
});

test('npm publish --dry-run accepts the package', () => {
  // npm 10 keys the report by package name; older versions give the report itself.
  const report = JSON.parse(npm(['publish', '--dry-run', '--json'], join(ROOT, 'pkg')));
  const out = report['texsynth-wasm'] ?? report;
  assert.equal(out.name, 'texsynth-wasm');
  for (const file of ['LICENSE-MIT', 'LICENSE-APACHE', 'README.md']) assert.ok(out.files.some((f) => f.path === file), file);
});
