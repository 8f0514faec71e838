// No leaks: 1,000 tiny sessions of every type are made, stepped and freed, or dropped
// for wasm-bindgen's FinalizationRegistry to free (the generated glue registers every object;
// see pkg/texsynth.js), and the wasm memory must end within 1 MiB of its size after the first 10.
// Each mode runs in its own `node --expose-gc` (leak_run.mjs), both at once, on the
// single-threaded module and on the threaded one.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { promisify } from 'node:util';
import { existsSync } from 'node:fs';

const threadedBuilt = existsSync(new URL('../../pkg/threads/texsynth_bg.wasm', import.meta.url));

const SESSIONS = 1000;
const LIMIT = 1 << 20;
const run = promisify(execFile);

async function measure(mode, build) {
  const script = new URL('./leak_run.mjs', import.meta.url).pathname;
  const env = { ...process.env, TEXSYNTH_TEST_BUILD: build };
  const { stdout } = await run(process.execPath, ['--expose-gc', script, mode, String(SESSIONS)], { maxBuffer: 1 << 20, env });
  return stdout.trim().split('\n').map((line) => ({ ...JSON.parse(line), build }));
}

async function leaks(build) {
  const results = (await Promise.all([measure('free', build), measure('drop', build)])).flat();
  for (const r of results) {
    console.log(`leaks (${build}): ${r.kind} (${r.mode}) ${r.afterTen} -> ${r.end} bytes (+${r.growth}) in ${r.ms} ms`);
  }
  assert.ok(results.length >= 2 * 9, `${results.length} results`);
  const over = results.filter((r) => r.growth > LIMIT);
  assert.deepEqual(over.map((r) => `${r.kind} (${r.mode}, ${build}): +${r.growth} bytes`), []);
}

test('1,000 sessions of each type, freed or dropped, leave wasm memory within 1 MiB', { timeout: 300_000 }, () => leaks('single'));

test('the same on the threaded module', { timeout: 300_000 }, async (t) => {
  if (!threadedBuilt) return t.skip('no threaded module in pkg/ (built without the nightly)');
  await leaks('threads');
});
