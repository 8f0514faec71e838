// The explicit initialiser shared by every entry point: wasm-bindgen's generated `init` wants
// `{ module_or_path }`; this one also takes the input itself (a URL or path string, a `Request`,
// a `Response` or a promise of one, bytes, or a `WebAssembly.Module`). Calling it again after the
// module is loaded is a no-op that returns the same exports, so it is safe in every environment.
import * as lib from './texsynth.js';
import { installProtocols } from './iterate.js';

const { default: generatedInit, initSync: generatedInitSync } = lib;
installProtocols(lib);

const isOptionsObject = (input) =>
  input !== null && typeof input === 'object' && !(input instanceof URL) &&
  ('module_or_path' in input || 'module' in input);

/** Loads the wasm module from `input` (default: `texsynth_bg.wasm` beside this file). */
export default function init(input) {
  if (input === undefined || isOptionsObject(input)) return generatedInit(input);
  return generatedInit({ module_or_path: input });
}
export { init };

/** Synchronous initialisation from bytes or a `WebAssembly.Module`. */
export function initSync(input) {
  if (isOptionsObject(input)) return generatedInitSync(input);
  return generatedInitSync({ module: input });
}
