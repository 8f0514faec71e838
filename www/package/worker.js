// `texsynth-wasm/worker` in browsers: sessions in module Web Workers. Bundlers (Vite, webpack 5)
// recognise `new Worker(new URL('./worker-web.js', import.meta.url), { type: 'module' })` and
// bundle the worker with its .wasm.
import { MirrorSession, TexsynthWorker, WorkerPool, WorkerSession } from './worker-client.js';

export function spawnWorker() {
  const worker = new Worker(new URL('./worker-web.js', import.meta.url), { type: 'module' });
  return {
    postMessage: (message, transfer) => worker.postMessage(message, transfer),
    onMessage: (handler) => worker.addEventListener('message', (e) => handler(e.data)),
    onError: (handler) => worker.addEventListener('error', (e) => handler(e.error ?? new Error(e.message))),
    terminate: () => worker.terminate(),
  };
}

/** A new worker hosting sessions. */
export const createWorker = () => new TexsynthWorker(spawnWorker);
/** A pool of `size` workers (default: hardware concurrency, at most 4). */
export const createPool = (size = Math.min(4, globalThis.navigator?.hardwareConcurrency ?? 2)) => new WorkerPool(spawnWorker, size);
export { MirrorSession, TexsynthWorker, WorkerPool, WorkerSession };
