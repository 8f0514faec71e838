// Web Worker script: the package inside a module (or bundled classic) worker. No top-level await,
// so bundlers may emit it in any worker format (Vite's default is iife).
import * as lib from './web.js';
import { serve } from './worker-serve.js';

lib.init(new URL('./texsynth_bg.wasm', import.meta.url)).then(
  () => {
    serve(lib, {
      post: (message, transfer) => self.postMessage(message, transfer),
      listen: (handler) => self.addEventListener('message', (e) => handler(e.data)),
    });
    self.postMessage({ type: 'ready' });
  },
  (error) => self.postMessage({ type: 'failed', message: error?.message ?? String(error) }),
);
