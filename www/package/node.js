// The Node entry point (`node` condition of the package's exports): the wasm is read from the
// package's own file and instantiated synchronously at import, so no `init()` and no network.
import { readFileSync } from 'node:fs';
import { initSync } from './init.js';

initSync(readFileSync(new URL('./texsynth_bg.wasm', import.meta.url)));

export * from './texsynth.js';
export { default, init, initSync } from './init.js';
export { yieldToEventLoop } from './iterate.js';
