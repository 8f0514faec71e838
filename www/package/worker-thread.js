// worker_threads script: the package's Node entry inside a Node worker.
import { parentPort } from 'node:worker_threads';
import * as lib from './node.js';
import { serve } from './worker-serve.js';

serve(lib, {
  post: (message, transfer) => parentPort.postMessage(message, transfer),
  listen: (handler) => parentPort.on('message', handler),
});
parentPort.postMessage({ type: 'ready' });
