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

export const createWorker = () => new TexsynthWorker(spawnWorker);
export const createPool = (size = Math.min(4, availableParallelism())) => new WorkerPool(spawnWorker, size);
export { MirrorSession, TexsynthWorker, WorkerPool, WorkerSession };
