// The bad-input corpus (corpus.mjs) against the built package: every row must give a JS Error
// naming the problem or a documented result; never a trap (a Rust panic kills the wasm
// instance) and never a hang (a row still running after ROW_TIMEOUT_MS fails, named). The corpus
// runs on the single-threaded module and on the threaded one.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Worker } from 'node:worker_threads';
import { existsSync } from 'node:fs';

const ROW_TIMEOUT_MS = 20_000;

const threadedBuilt = existsSync(new URL('../../pkg/threads/texsynth_bg.wasm', import.meta.url));

/** Runs the rows on `build` (see fixtures.mjs) in workers; resolves with every row's result. */
function runCorpus(build) {
  return new Promise((resolve) => {
    const results = [];
    let count = Infinity;
    const startAt = (start) => {
      const env = { ...process.env, TEXSYNTH_TEST_BUILD: build };
      const worker = new Worker(new URL('./corpus_worker.mjs', import.meta.url), { workerData: { start }, env });
      let current = { index: start, name: '(loading)' };
      let timer;
      const arm = () => {
        clearTimeout(timer);
        timer = setTimeout(() => {
          results.push({ ...current, outcome: 'hang', pass: false, why: `still running after ${ROW_TIMEOUT_MS} ms` });
          worker.terminate();
          next(current.index + 1);
        }, ROW_TIMEOUT_MS);
      };
      let moved = false;
      const next = (at) => {
        if (moved) return;
        moved = true;
        clearTimeout(timer);
        if (at < count) startAt(at);
        else resolve(results);
      };
      arm();
      worker.on('message', (m) => {
        if (m.count !== undefined) count = m.count;
        if (m.started !== undefined) {
          current = { index: m.started, name: m.name };
          arm();
        }
        if (m.index !== undefined) {
          results.push(m);
          if (m.outcome === 'trap') next(m.index + 1);
        }
        if (m.finished) next(count);
      });
      worker.on('error', (error) => {
        results.push({ ...current, outcome: 'worker error', pass: false, why: String(error?.stack ?? error) });
        // A worker that failed before it knew the rows (a syntax error, no package) cannot go on.
        if (count === Infinity) count = 0;
        next(current.index + 1);
      });
    };
    startAt(0);
  });
}

async function corpus(build) {
  const results = await runCorpus(build);
  const failed = results.filter((r) => !r.pass);
  const slowest = results.reduce((a, b) => (b.ms > (a?.ms ?? -1) ? b : a), null);
  console.log(`corpus (${build}): ${results.length} rows, ${failed.length} failed; slowest ${slowest?.name} ${slowest?.ms?.toFixed(0)} ms`);
  for (const r of failed) console.log(`FAIL [${r.index}] ${r.name}: ${r.why}`);
  assert.equal(failed.length, 0, failed.map((r) => `${r.name}: ${r.why}`).join('\n'));
  assert.ok(results.length > 300, `the corpus has ${results.length} rows`);
}

test('bad input to every JS entry point gives a named error or a documented result', { timeout: 600_000 }, () => corpus('single'));

test('the same on the threaded module', { timeout: 600_000 }, async (t) => {
  if (!threadedBuilt) return t.skip('no threaded module in pkg/ (built without the nightly)');
  await corpus('threads');
});
