// Determinism: the same seed, options and input give byte-identical output across
// runs, between the native build and the wasm package, and whatever the size of the Worker pool.
//
// Native and wasm agree because every transcendental function goes through src/core/math.rs (the
// `libm` crate on both; glibc's expf/powf round differently from wasm's in ~10% of cases), and
// the texture-optimisation IRLS weight through src/core/power.rs (plain arithmetic).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { CASES, fnv1a, runCase } from './determinism_cases.mjs';
import { api, sampleBytes } from './fixtures.mjs';

const ROOT = new URL('../../', import.meta.url).pathname;

test('same seed and options: the same bytes on a second run in the same instance', () => {
  const first = CASES.map((c) => fnv1a(runCase(c)));
  const second = [...CASES].reverse().map((c) => fnv1a(runCase(c))).reverse();
  assert.deepEqual(second, first);
});

test('native and wasm give byte-identical outputs', { timeout: 900_000 }, () => {
  // Built in the dev profile that `cargo test` has already compiled the library in.
  const stdout = execFileSync('cargo', ['test', '--quiet', '--test', 'determinism_hashes'], {
    cwd: ROOT, encoding: 'utf8', stdio: ['ignore', 'pipe', 'inherit'],
  });
  const native = Object.fromEntries(stdout.trim().split('\n').map((line) => line.split(' ')));
  const wasm = Object.fromEntries(CASES.map((c) => [c.name, fnv1a(runCase(c))]));
  assert.deepEqual(Object.keys(native).sort(), Object.keys(wasm).sort(), 'the same cases on both sides');
  const differ = CASES.filter((c) => native[c.name] !== wasm[c.name]).map((c) => `${c.name}: native ${native[c.name]}, wasm ${wasm[c.name]}`);
  console.log(`determinism: ${CASES.length - differ.length} of ${CASES.length} cases identical native/wasm`);
  assert.deepEqual(differ, []);
});

test('the Worker pool size changes no output', { timeout: 300_000 }, async () => {
  const { createPool } = await import('../../pkg/worker-node.js');
  const jobs = CASES.filter((c) => c.kind !== 'LayerDesign');
  const expected = jobs.map((c) => fnv1a(runCase(c)));
  for (const size of [1, 3]) {
    const pool = createPool(size);
    try {
      const images = await Promise.all(jobs.map((c) => {
        const exemplar = api.Exemplar.fromBytes(sampleBytes(c.sample));
        return pool.run(c.kind, [exemplar, c.options]).finally(() => exemplar.free());
      }));
      assert.deepEqual(images.map((r) => fnv1a(r.image.data ?? new Uint8Array(r.image.image))), expected, `pool of ${size}`);
    } finally {
      pool.close();
    }
  }
});

test('the threaded module gives the same bytes at 1, 2 and 4 threads', { timeout: 600_000 }, async () => {
  if (!existsSync(new URL('../../pkg/threads/texsynth_bg.wasm', import.meta.url))) {
    // The build shipped the single-threaded module alone: then no threaded entry may be left.
    assert.equal(existsSync(new URL('../../pkg/threads.js', import.meta.url)), false);
    console.log('determinism: no threaded module in pkg/ (built without the nightly)');
    return;
  }
  const threads = await import('../../pkg/threads.js');
  assert.equal(threads.threaded(), true);
  assert.equal(api.threaded(), false);
  assert.equal(api.threadCount(), 1);
  const expected = CASES.map((c) => fnv1a(runCase(c)));
  for (const n of [1, 2, 4]) {
    assert.equal(await threads.initThreadPool(n), n);
    assert.equal(threads.threadCount(), n);
    const got = CASES.map((c) => fnv1a(runCase(c, threads)));
    const differ = CASES.filter((c, i) => got[i] !== expected[i]).map((c) => c.name);
    assert.deepEqual(differ, [], `${n} threads`);
  }
  console.log(`determinism: ${CASES.length} cases identical on the threaded module at 1, 2 and 4 threads`);
});

test('natively, the parallel feature gives the same bytes at 1, 2 and 4 threads', { timeout: 900_000 }, () => {
  const hashes = (features, threads) => execFileSync('cargo', ['test', '--quiet', ...features, '--test', 'determinism_hashes'], {
    cwd: ROOT, encoding: 'utf8', stdio: ['ignore', 'pipe', 'inherit'],
    env: { ...process.env, RAYON_NUM_THREADS: String(threads) },
  });
  const serial = hashes([], 1);
  for (const n of [1, 2, 4]) {
    assert.equal(hashes(['--features', 'parallel'], n), serial, `rayon with ${n} threads`);
  }
  console.log('determinism: native outputs identical without rayon and with 1, 2 and 4 threads');
});
