// No leaks: 1,000 tiny sessions of every type are made, stepped and freed, or dropped
// for wasm-bindgen's FinalizationRegistry to free (the generated glue registers every object;
// see pkg/texsynth.js), and the wasm memory must end within 1 MiB of its size after the first 10.
// Each mode runs in its own `node --expose-gc` (leak_run.mjs), both at once.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { promisify } from 'node:util';

const SESSIONS = 1000;
const LIMIT = 1 << 20;
const run = promisify(execFile);

async function measure(mode) {
  const script = new URL('./leak_run.mjs', import.meta.url).pathname;
  const { stdout } = await run(process.execPath, ['--expose-gc', script, mode, String(SESSIONS)], { maxBuffer: 1 << 20 });
  return stdout.trim().split('\n').map((line) => JSON.parse(line));
}

test('1,000 sessions of each type, freed or dropped, leave wasm memory within 1 MiB', { timeout: 300_000 }, async () => {
  const results = (await Promise.all([measure('free'), measure('drop')])).flat();
  for (const r of results) {
    console.log(`leaks: ${r.kind} (${r.mode}) ${r.afterTen} -> ${r.end} bytes (+${r.growth}) in ${r.ms} ms`);
  }
  assert.ok(results.length >= 2 * 9, `${results.length} results`);
  const over = results.filter((r) => r.growth > LIMIT);
  assert.deepEqual(over.map((r) => `${r.kind} (${r.mode}): +${r.growth} bytes`), []);
});
