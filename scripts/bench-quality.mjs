// Times measureQuality in wasm (Node) on a few finished outputs, for one build or two against
// each other: `node scripts/bench-quality.mjs [DIR_A] [DIR_B]` (each a built package, as pkg/
// after ./scripts/build.sh; default pkg). The outputs are made once with the first build; each
// is scored twice per build, alternating, and the fastest run is printed, with whether both
// builds gave the same figures.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const dirs = process.argv.slice(2);
if (dirs.length === 0) dirs.push('pkg');
const libs = await Promise.all(dirs.map((d) => import(pathToFileURL(resolve(d, 'node.js')).href)));
const sample = (name) => readFileSync(new URL(`../www/samples/${name}.png`, import.meta.url));
const CASES = [
  ['TextureOptimization', 'tiles_128', 256],
  ['GraphcutTextures', 'gravel_128', 256],
  ['GraphcutTextures', 'tiles_128', 512],
  ['GraphcutTextures', 'tiles_128', 1024],
];
for (const [kind, name, size] of CASES) {
  const lib = libs[0];
  const exemplar = lib.Exemplar.fromBytes(sample(name));
  const session = new lib[kind](exemplar, { outputWidth: size, outputHeight: size, seed: 1 });
  while (!session.step().done);
  const rgba = new Uint8Array(size * size * 4);
  session.renderInto(new Uint8ClampedArray(rgba.buffer));
  session.free();
  exemplar.free();
  const times = libs.map(() => []);
  const figures = [];
  for (let round = 0; round < 2; round++) {
    libs.forEach((l, k) => {
      const ex = l.Exemplar.fromBytes(sample(name));
      const start = performance.now();
      figures[k] = JSON.stringify(l.measureQuality(ex, rgba, size, size));
      times[k].push(performance.now() - start);
      ex.free();
    });
  }
  const cols = times.map((t, k) => `${dirs[k]} ${Math.min(...t).toFixed(0)} ms`).join(', ');
  const same = libs.length > 1 ? `; same figures: ${figures.every((f) => f === figures[0])}` : '';
  console.log(`${kind} ${name} ${size}x${size}: ${cols}${same}`);
}
