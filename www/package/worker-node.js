// `texsynth-wasm/worker` in Node: the same API over worker_threads.
import { availableParallelism } from 'node:os';
import { Worker } from 'node:worker_threads';
import { MirrorSession, TexsynthWorker, WorkerPool, WorkerSession } from './worker-client.js';

export function spawnWorker() {
  const worker = new Worker(new URL('./worker-thread.js', import.meta.url));
  return {
    postMessage: (message, transfer) => worker.postMessage(message, transfer),
    onMessage: (handler) => worker.on('message', handler),
    onError: (handler) => worker.on('error', handler),
    terminate: () => worker.terminate(),
  };
}

/**
 * A new worker hosting sessions. `threads`: 'auto' (default) runs the threaded module on every
 * core when the package has it and the single-threaded one otherwise; a number asks for that many
 * threads; false asks for the single-threaded module.
 */
export const createWorker = ({ threads = 'auto' } = {}) => new TexsynthWorker(spawnWorker, { threads });
/** A pool of `size` workers (default: every core, at most 4), single-threaded unless `threads` says otherwise. */
export const createPool = (size = Math.min(4, availableParallelism()), { threads = false } = {}) =>
  new WorkerPool(spawnWorker, size, { threads });
export { MirrorSession, TexsynthWorker, WorkerPool, WorkerSession };
