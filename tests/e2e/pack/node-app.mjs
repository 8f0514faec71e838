// The README's Node example, run by tests/e2e/npm_pack.test.mjs in a scratch project.
import { readFileSync } from 'node:fs';
import { Exemplar, TextureOptimization, GraphcutTextures, measureQuality, version } from 'texsynth-wasm';

const exemplar = Exemplar.fromBytes(readFileSync(process.argv[2]));
const session = new TextureOptimization(exemplar, { outputWidth: 64, outputHeight: 64, seed: 3, neighbourhoodSizes: [16, 8] });
let steps = 0;
for (const event of session) steps++;                     // sessions are iterable
const output = new Uint8ClampedArray(session.width * session.height * 4);
session.renderInto(output);
const quality = measureQuality(exemplar, output, session.width, session.height);

const graphcut = new GraphcutTextures(exemplar, { outputWidth: 96, outputHeight: 96 });
const controller = new AbortController();
let placed = 0;
let aborted = '';
try {
  await graphcut.run({ signal: controller.signal, onEvent: () => ++placed === 3 && controller.abort() });
} catch (error) {
  aborted = error.name;                                    // 'AbortError'
}

let error = '';
try { Exemplar.fromBytes(new Uint8Array(0)); } catch (e) { error = e instanceof Error ? e.message : 'not an Error'; }
console.log(JSON.stringify({ version: version(), steps, done: session.done, coherence: quality.coherence, placed, aborted, error }));
