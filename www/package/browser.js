// The browser and bundler entry point (the `default` condition): loads `texsynth_bg.wasm` from
// beside this file with top-level await. Bundlers (Vite, webpack 5, Rollup with its URL plugin)
// see `new URL('./texsynth_bg.wasm', import.meta.url)` and emit the .wasm as an ordinary asset;
// a plain page that imports this file (relative path or import map) fetches it from the same folder.
// To load the .wasm from elsewhere, import 'texsynth-wasm/web' and call `init(url)` yourself.
import init from './init.js';

await init(new URL('./texsynth_bg.wasm', import.meta.url));

export * from './texsynth.js';
export { default, init, initSync } from './init.js';
export { yieldToEventLoop } from './iterate.js';
