// The explicit entry point (`texsynth-wasm/web`): nothing is loaded until you call
// `await init(input)` with a URL, a path, a Response, bytes or a WebAssembly.Module (or nothing:
// then `texsynth_bg.wasm` beside this file).
export * from './texsynth.js';
export { default, init, initSync } from './init.js';
export { yieldToEventLoop } from './iterate.js';
