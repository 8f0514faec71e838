// Feature-guided synthesis (Wu & Yu 2004) against plain graph-cut textures in wasm under Node,
// 256x256 from the 128x128 samples, seed 1:
//   node scripts/bench-features.mjs [--samples squares_128,planks_128,...]
// Prints time, coherence, flat fraction and the broken-feature counts (curve ends per 1000 curve
// pixels above the exemplar's own; lower is better) for both methods: `broken` on maps detected
// on the outputs, `seams` on the carried (synthesised) maps, where each output pixel carries the
// exemplar's curve at the pixel it shows (the curves seams cut).
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import init, { detectFeatures, Exemplar, FeatureSynthesis, GraphcutTextures, measureBrokenFeatures, measureQuality } from '../pkg/texsynth.js';

const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, arg, i, all) => (arg.startsWith('--') ? [...pairs, [arg.slice(2), all[i + 1]]] : pairs), []),
);
await init({ module_or_path: readFileSync(new URL('../pkg/texsynth_bg.wasm', import.meta.url)) });
const samples = (args.samples ?? 'squares_128,planks_128,carpet_128,brick_128,tiles_128,paving_128').split(',');

console.log(`wasm (Node ${process.version}) feature-guided against graph cut, 256x256, seed 1`);
console.log('exemplar      method           ms   coherence    flat   broken    seams');
let wins = 0;
let seamWins = 0;
for (const name of samples) {
  const ex = Exemplar.fromBytes(readFileSync(new URL(`../www/samples/${name}.png`, import.meta.url)));
  const figures = {};
  const seams = {};
  const map = detectFeatures(ex);
  const mask = map.toMask();
  for (const [method, make] of [
    ['feature-guided', () => new FeatureSynthesis(ex, { outputWidth: 256, outputHeight: 256 })],
    ['graph cut', () => new GraphcutTextures(ex, { outputWidth: 256, outputHeight: 256 })],
  ]) {
    const start = performance.now();
    const s = make();
    while (!s.step().done);
    const ms = performance.now() - start;
    const rgba = new Uint8ClampedArray(256 * 256 * 4);
    s.renderInto(rgba);
    const q = measureQuality(ex, rgba, 256, 256);
    const broken = measureBrokenFeatures(ex, rgba, 256, 256, undefined);
    figures[method] = broken;
    seams[method] = s instanceof FeatureSynthesis ? s.carriedBrokenFeatures() : s.carriedBrokenFeatures(mask);
    console.log(`${name.padEnd(13)} ${method.padEnd(14)} ${ms.toFixed(0).padStart(6)} ${q.coherence.toExponential(2).padStart(11)} ${q.flat.toFixed(3).padStart(7)} ${broken.toFixed(1).padStart(8)} ${seams[method].toFixed(1).padStart(8)}`);
    s.free();
  }
  if (figures['feature-guided'] < figures['graph cut']) wins++;
  if (seams['feature-guided'] < seams['graph cut']) seamWins++;
  map.free();
  ex.free();
}
console.log(`feature-guided breaks fewer features on ${wins} of ${samples.length} (detected), ${seamWins} of ${samples.length} (at seams)`);
