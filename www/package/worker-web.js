// Web Worker script: the package inside a module (or bundled classic) worker. No top-level await,
// so bundlers may emit it in any worker format (Vite's default is iife). The first message says
// which module to run (worker-module.js).
import * as web from './web.js';
import { loadModule } from './worker-module.js';
import { serve } from './worker-serve.js';

const unavailable = self.crossOriginIsolated !== true
  ? 'the page is not cross-origin isolated (it needs Cross-Origin-Opener-Policy: same-origin and Cross-Origin-Embedder-Policy: require-corp)'
  : null;

self.addEventListener('message', function init(e) {
  if (e.data?.type !== 'init') return;
  self.removeEventListener('message', init);
  loadModule(e.data.threads, {
    single: () => web.init(new URL('./texsynth_bg.wasm', import.meta.url)).then(() => web),
    threadsUrl: new URL('./threads.js', import.meta.url),
    unavailable,
  }).then(
    ({ lib, info }) => {
      serve(lib, {
        post: (message, transfer) => self.postMessage(message, transfer),
        listen: (handler) => self.addEventListener('message', (event) => handler(event.data)),
      });
      self.postMessage({ type: 'ready', ...info });
    },
    (error) => self.postMessage({ type: 'failed', message: error?.message ?? String(error) }),
  );
});
