// One thread of the threaded module's pool (threads.js starts it): a Web Worker or a Node worker
// thread that instantiates the module on the shared memory it is sent, says it is ready, and then
// runs its pool thread until the pool is replaced.
const node = typeof process === 'object' && Boolean(process.versions?.node);
const port = node ? (await import('node:worker_threads')).parentPort : globalThis;

function once(handler) {
  if (node) port.once('message', handler);
  else port.addEventListener('message', (event) => handler(event.data), { once: true });
}

once(async ({ module, memory }) => {
  const wasm = await import('./threads/texsynth.js');
  wasm.initSync({ module, memory });
  port.postMessage('ready');
  wasm.runPoolThread();
  if (node) process.exit(0);
  else globalThis.close();
});
