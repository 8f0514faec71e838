// Web Worker script: the package's browser entry inside a module worker.
import * as lib from './browser.js';
import { serve } from './worker-serve.js';

serve(lib, {
  post: (message, transfer) => self.postMessage(message, transfer),
  listen: (handler) => self.addEventListener('message', (e) => handler(e.data)),
});
self.postMessage({ type: 'ready' });
