// Texture design (Shen et al. 2009) in wasm under Node, one thread:
//   node scripts/bench-design.mjs [--sample tiles_128] [--energy-samples squares_128,planks_128,...]
// - layer-based design, 360x360, patches of 32/64/92 (Table 2): QTP against exhaustive search,
//   best match, time and total boundary SSD;
// - making a 256x256 and a 1024x1024 image tileable;
// - one brush stroke (labelling + Poisson paste) on a 256x256 base;
// - synthesis with the pixel, Haar and Daubechies energies (time and quality) when the
//   texture-optimization build has the `energy` option.
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import init, {
  Exemplar, LayerDesign, TextureBrush, TextureOptimization, deformTexture, makeTileable, measureQuality,
} from '../pkg/texsynth.js';

const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, arg, i, all) => (arg.startsWith('--') ? [...pairs, [arg.slice(2), all[i + 1]]] : pairs), []),
);
await init({ module_or_path: readFileSync(new URL('../pkg/texsynth_bg.wasm', import.meta.url)) });
const load = (name) => Exemplar.fromBytes(readFileSync(new URL(`../www/samples/${name}.png`, import.meta.url)));
const sample = args.sample ?? 'tiles_128';
const texture = load(sample);

console.log(`wasm (Node ${process.version}) layer-based design, ${sample}, 360x360, best match`);
console.log('patch  search       ms      total SSD   pixel differences');
for (const patchSize of [32, 64, 92]) {
  const figures = {};
  for (const search of ['qtp', 'exhaustive']) {
    const start = performance.now();
    const design = new LayerDesign({ outputWidth: 360, outputHeight: 360, patchSize, search, placement: 'best' });
    design.addLayer(texture, undefined);
    let event;
    do event = design.step(); while (!event.done);
    const ms = performance.now() - start;
    figures[search] = { ms, ssd: event.totalSsd };
    console.log(`${String(patchSize).padStart(5)}  ${search.padEnd(10)} ${ms.toFixed(0).padStart(6)} ${event.totalSsd.toFixed(1).padStart(14)} ${String(event.pixelsCompared).padStart(19)}`);
    design.free();
  }
  console.log(`       QTP ${(figures.exhaustive.ms / figures.qtp.ms).toFixed(1)}x faster, total SSD ${(100 * (figures.qtp.ssd / figures.exhaustive.ssd - 1)).toFixed(1)}% against exhaustive`);
}

console.log();
for (const [label, steps] of [['256x256', [{ scale: 2 }]], ['1024x1024', [{ scale: 4 }, { scale: 2 }]]]) {
  const image = deformTexture(texture, steps);
  const start = performance.now();
  const t = makeTileable(image, undefined);
  console.log(`make tileable ${label} (${image.width}x${image.height}): ${(performance.now() - start).toFixed(0)} ms`);
  t.exemplar.free();
  image.free();
}

const base = deformTexture(load('gravel_128'), { scale: 2 });
const reference = deformTexture(load('paving_128'), { scale: 2 });
const mask = new Uint8Array(reference.width * reference.height);
for (let y = 0; y < reference.height; y++) {
  for (let x = 0; x < reference.width; x++) {
    mask[y * reference.width + x] = ((x - 128) / 30) ** 2 + ((y - 120) / 20) ** 2 <= 1 ? 1 : 0;
  }
}
const times = [];
for (let i = 0; i < 5; i++) {
  const brush = new TextureBrush(base, undefined);
  const start = performance.now();
  brush.stroke(reference, mask, -20, 30);
  times.push(performance.now() - start);
  brush.free();
}
times.sort((a, b) => a - b);
console.log(`brush stroke on ${base.width}x${base.height} (60x40 ellipse): median ${times[2].toFixed(1)} ms of 5`);

const energySamples = (args['energy-samples'] ?? 'squares_128,planks_128,carpet_128,brick_128,tiles_128').split(',');
let hasEnergy = true;
try {
  new TextureOptimization(texture, { energy: 'haar', outputWidth: 32, outputHeight: 32 }).free();
} catch {
  hasEnergy = false;
}
if (hasEnergy) {
  console.log('\ntexture optimization energies, 256x256, seed 1 (lower is better; flat: the exemplar ~0.10)');
  console.log('exemplar      energy        ms   coherence  completeness   flat');
  for (const name of energySamples) {
    const ex = load(name);
    for (const energy of ['pixels', 'haar', 'daubechies']) {
      const start = performance.now();
      const s = new TextureOptimization(ex, { outputWidth: 256, outputHeight: 256, energy });
      while (!s.step().done);
      const ms = performance.now() - start;
      const rgba = new Uint8ClampedArray(256 * 256 * 4);
      s.renderInto(rgba);
      const q = measureQuality(ex, rgba, 256, 256);
      console.log(`${name.padEnd(13)} ${energy.padEnd(11)} ${ms.toFixed(0).padStart(6)} ${q.coherence.toExponential(2).padStart(11)} ${q.completeness.toExponential(2).padStart(13)} ${q.flat.toFixed(3).padStart(6)}`);
      s.free();
    }
    ex.free();
  }
}
