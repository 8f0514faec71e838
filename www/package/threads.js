// The threaded module: the same classes and functions as the default entry, on a rayon pool over
// Web Workers or Node worker threads that share the module's memory. It needs shared memory:
// Node, or a page that is cross-origin isolated (Cross-Origin-Opener-Policy: same-origin and
// Cross-Origin-Embedder-Policy: require-corp); `threadsSupported()` tells. In a browser, use it
// from a Worker: the main thread may not wait for the pool.
//
// Importing it loads the module and starts a pool of `os.availableParallelism()` or
// `navigator.hardwareConcurrency` threads; `initThreadPool(n)` replaces the pool with one of n.
import * as wasm from './threads/texsynth.js';
import { installProtocols } from './iterate.js';

export * from './threads/texsynth.js';
export { yieldToEventLoop } from './iterate.js';

installProtocols(wasm);

const node = typeof process === 'object' && Boolean(process.versions?.node);

/** Whether this environment can run the threaded module (shared memory and workers). */
export function threadsSupported() {
  if (typeof SharedArrayBuffer !== 'function') return false;
  if (node) return true;
  return globalThis.crossOriginIsolated === true && typeof Worker === 'function';
}

/** The thread count the package starts with: every core the environment reports. */
export async function defaultThreadCount() {
  if (node) return (await import('node:os')).availableParallelism();
  return Math.max(1, globalThis.navigator?.hardwareConcurrency ?? 1);
}

async function spawn(url, init) {
  if (node) {
    const { Worker } = await import('node:worker_threads');
    const worker = new Worker(url);
    await new Promise((resolve, reject) => {
      worker.once('message', resolve);
      worker.once('error', reject);
      worker.postMessage(init);
    });
    // A pool thread must not keep the process alive.
    worker.unref();
    return worker;
  }
  const worker = new Worker(url, { type: 'module' });
  await new Promise((resolve, reject) => {
    worker.addEventListener('message', resolve, { once: true });
    worker.addEventListener('error', (e) => reject(new Error(`a pool worker failed to start: ${e.message}`)), { once: true });
    worker.postMessage(init);
  });
  return worker;
}

let pending = Promise.resolve();

/**
 * Starts a pool of `threads` threads (1 to 64; default: every core) and resolves to its size once
 * every thread runs. A pool started earlier is replaced when the new one is ready. Same seed,
 * same bytes: the thread count changes the time, never the output.
 */
export function initThreadPool(threads) {
  const start = async () => {
    const n = threads ?? (await defaultThreadCount());
    if (!Number.isInteger(n) || n < 1 || n > 64) {
      throw new Error(`threads must be a whole number from 1 to 64, got ${n}`);
    }
    wasm.prepareThreadPool(n);
    const init = { module: wasm.threadPoolModule(), memory: wasm.threadPoolMemory() };
    const url = new URL('./threads-worker.js', import.meta.url);
    await Promise.all(Array.from({ length: n }, () => spawn(url, init)));
    return wasm.activateThreadPool();
  };
  pending = pending.then(start, start);
  return pending;
}

if (node) {
  const { readFileSync } = await import('node:fs');
  wasm.initSync({ module: readFileSync(new URL('./threads/texsynth_bg.wasm', import.meta.url)) });
  const env = process.env.TEXSYNTH_THREADS;
  await initThreadPool(env ? Number(env) : undefined);
} else {
  await wasm.default({ module_or_path: new URL('./threads/texsynth_bg.wasm', import.meta.url) });
  await initThreadPool();
}
