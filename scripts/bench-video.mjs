#!/usr/bin/env node
// Graph-cut video textures as wasm in Node, on the demo clip (www/samples/clips/water.png, made by
// scripts/make-demo-clip.mjs): a 128x128x60 loop (goal: at most 10 s) and a spatial extension of
// 96x96x30 to 192x192x60 (goal: at most 30 s), with random, sub-patch and entire-patch placement
// (the last has no goal: its search spans twice the clip along each axis). Needs pkg/
// (./scripts/build.sh). The 3-D FFT search against direct SSD is in the native
// `cargo run --profile explore -p texsynth-bench --bin video_bench`.
//   node scripts/bench-video.mjs [--seed 1]
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import init, { Exemplar, VideoClip, VideoTextures } from '../pkg/texsynth.js';

const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, arg, i, all) => (arg.startsWith('--') ? [...pairs, [arg.slice(2), all[i + 1]]] : pairs), []),
);
const seed = Number(args.seed ?? 1);
await init({ module_or_path: readFileSync(new URL('../pkg/texsynth_bg.wasm', import.meta.url)) });

const strip = Exemplar.fromBytes(readFileSync(new URL('../www/samples/clips/water.png', import.meta.url)));
const stripRgba = strip.toRgba();
const SIDE = 128;

/** The first `frames` frames of the demo clip, resampled (nearest) to `side` x `side`. */
function clip(side, frames) {
  const out = new Uint8Array(side * side * 4 * frames);
  for (let t = 0; t < frames; t++) {
    for (let y = 0; y < side; y++) {
      for (let x = 0; x < side; x++) {
        const sx = Math.floor((x * SIDE) / side);
        const sy = Math.floor((y * SIDE) / side);
        const from = ((t * SIDE + sy) * SIDE + sx) * 4;
        out.set(stripRgba.subarray(from, from + 4), ((t * side + y) * side + x) * 4);
      }
    }
  }
  return VideoClip.fromFrames(side, side, frames, out);
}

const cases = [
  { name: 'loop 128x128x60', side: 128, frames: 60, options: { mode: 'loop' }, goal: 10 },
  { name: 'extend 96x96x30 -> 192x192x60, random', side: 96, frames: 30, options: { mode: 'extend', outputWidth: 192, outputHeight: 192, outputFrames: 60, placement: 'random' }, goal: 30 },
  { name: 'extend 96x96x30 -> 192x192x60, sub-patch', side: 96, frames: 30, options: { mode: 'extend', outputWidth: 192, outputHeight: 192, outputFrames: 60, placement: 'sub-patch' }, goal: 30 },
  { name: 'extend 96x96x30 -> 192x192x60, entire-patch', side: 96, frames: 30, options: { mode: 'extend', outputWidth: 192, outputHeight: 192, outputFrames: 60, placement: 'entire-patch' }, goal: '-' },
];

console.log(`wasm (Node ${process.version}) graph-cut video textures on the demo clip, seed ${seed}`);
console.log(`${'case'.padEnd(42)} ${'patches'.padStart(8)} ${'total s'.padStart(8)} ${'max step ms'.padStart(12)} ${'goal s'.padStart(7)}  output`);
for (const c of cases) {
  const input = clip(c.side, c.frames);
  const started = performance.now();
  const video = new VideoTextures(input, { ...c.options, seed });
  let patches = 0;
  let longest = 0;
  let event = null;
  while (!video.done) {
    const t = performance.now();
    event = video.step();
    longest = Math.max(longest, performance.now() - t);
    if (event.patch !== null) patches++;
  }
  const seconds = (performance.now() - started) / 1000;
  const loop = event?.loopFrame != null ? `, loop closes at frame ${event.loopFrame + 1}` : '';
  console.log(`${c.name.padEnd(42)} ${String(patches).padStart(8)} ${seconds.toFixed(1).padStart(8)} ${longest.toFixed(0).padStart(12)} ${String(c.goal).padStart(7)}  ${video.width}x${video.height}x${video.frames}${loop}`);
  video.free();
  input.free();
}
