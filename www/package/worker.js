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

/**
 * A new worker hosting sessions. `threads`: 'auto' (default) runs the threaded module on every
 * core where the page is cross-origin isolated and the single-threaded one elsewhere; a number
 * asks for that many threads; false asks for the single-threaded module.
 */
export const createWorker = ({ threads = 'auto' } = {}) => new TexsynthWorker(spawnWorker, { threads });
/**
 * A pool of `size` workers (default: hardware concurrency, at most 4), each running one session at
 * a time. The pool spreads sessions over cores, so its workers are single-threaded unless
 * `threads` says otherwise.
 */
export const createPool = (size = Math.min(4, globalThis.navigator?.hardwareConcurrency ?? 2), { threads = false } = {}) =>
  new WorkerPool(spawnWorker, size, { threads });
export { MirrorSession, TexsynthWorker, WorkerPool, WorkerSession };
