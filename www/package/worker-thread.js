// worker_threads script: the package's Node entry inside a Node worker. The first message says
// which module to run (worker-module.js).
import { existsSync } from 'node:fs';
import { parentPort } from 'node:worker_threads';
import { loadModule } from './worker-module.js';
import { serve } from './worker-serve.js';

const unavailable = existsSync(new URL('./threads/texsynth_bg.wasm', import.meta.url))
  ? null
  : 'this package has no threaded module (it was built without the nightly toolchain)';

parentPort.once('message', async ({ threads }) => {
  try {
    const { lib, info } = await loadModule(threads, {
      single: () => import('./node.js'),
      threadsUrl: new URL('./threads.js', import.meta.url),
      unavailable,
    });
    serve(lib, {
      post: (message, transfer) => parentPort.postMessage(message, transfer),
      listen: (handler) => parentPort.on('message', handler),
    });
    parentPort.postMessage({ type: 'ready', ...info });
  } catch (error) {
    parentPort.postMessage({ type: 'failed', message: error?.message ?? String(error) });
  }
});
