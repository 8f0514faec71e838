// Benchmark of the wasm build in Node (one thread, the way a user runs it): texture optimisation
// 256x256 from the samples with each search. Usage:
//   node scripts/bench.mjs [--samples gravel_128,gravel_64] [--searches patchmatch,kmeans-tree,exact]
// Prints per case: steps, total time, time per step (median, max), final energy.
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import init, { Exemplar, TextureOptimization } from '../pkg/texsynth.js';

const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, arg, i, all) => (arg.startsWith('--') ? [...pairs, [arg.slice(2), all[i + 1]]] : pairs), []),
);
const samples = (args.samples ?? 'gravel_128,gravel_64,tiles_128').split(',');
const searches = (args.searches ?? 'patchmatch,kmeans-tree,exact').split(',');
const size = Number(args.size ?? 256);

await init({ module_or_path: readFileSync(new URL('../pkg/texsynth_bg.wasm', import.meta.url)) });

const pad = (v, n) => String(v).padStart(n);
console.log(`wasm (Node ${process.version}) texture optimization, ${size}x${size} output, default schedule (r = 0.8, seed 1)`);
console.log(`${'exemplar'.padEnd(12)} ${'search'.padEnd(12)} ${pad('steps', 6)} ${pad('total ms', 9)} ${pad('median ms', 10)} ${pad('max ms', 10)} ${pad('final energy', 12)}`);
for (const name of samples) {
  const exemplar = Exemplar.fromBytes(readFileSync(new URL(`../www/samples/${name}.png`, import.meta.url)));
  for (const search of searches) {
    const start = performance.now();
    const session = new TextureOptimization(exemplar, { outputWidth: size, outputHeight: size, search });
    const steps = [];
    let event;
    do {
      const t = performance.now();
      event = session.step();
      steps.push(performance.now() - t);
    } while (!event.done);
    const total = performance.now() - start;
    steps.sort((a, b) => a - b);
    const median = steps[Math.floor(steps.length / 2)];
    const max = steps[steps.length - 1];
    console.log(`${name.padEnd(12)} ${search.padEnd(12)} ${pad(steps.length, 6)} ${pad(total.toFixed(1), 9)} ${pad(median.toFixed(1), 10)} ${pad(max.toFixed(1), 10)} ${pad(event.energy.toFixed(6), 12)}`);
    session.free();
  }
  exemplar.free();
}
