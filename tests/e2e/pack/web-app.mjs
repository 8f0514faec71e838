// The explicit entry point in Node: init() with bytes.
import { readFileSync } from 'node:fs';
import { init, Exemplar } from 'texsynth-wasm/web';

const wasm = readFileSync(new URL(import.meta.resolve('texsynth-wasm/texsynth_bg.wasm')));
await init(await WebAssembly.compile(wasm));
console.log(Exemplar.fromBytes(readFileSync(process.argv[2])).width);
