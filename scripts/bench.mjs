// Benchmark of the wasm build in Node (one thread, the way a user runs it): texture optimisation
// with each search and graph-cut textures with each placement mode, 256x256 from the samples.
// Usage:
//   node scripts/bench.mjs [--samples gravel_128,gravel_64] [--searches patchmatch,kmeans-tree,exact]
//                          [--placements random,entire-patch,sub-patch] [--methods optimization,graphcut,flow]
//                          [--flow-sizes 128,256] [--flow-frames 40]
// Prints per case: steps, total time, time per step (median, max), final energy or seam cost; for
// flow animation, frames per second after the first frame and the coherence of the frames.
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import init, { Exemplar, FlowAnimation, GraphcutTextures, TextureOptimization, measureQuality } from '../pkg/texsynth.js';

const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, arg, i, all) => (arg.startsWith('--') ? [...pairs, [arg.slice(2), all[i + 1]]] : pairs), []),
);
const samples = (args.samples ?? 'gravel_128,gravel_64,tiles_128').split(',');
const searches = (args.searches ?? 'patchmatch,kmeans-tree,exact').split(',');
const placements = (args.placements ?? 'random,entire-patch,sub-patch').split(',');
const methods = (args.methods ?? 'optimization,graphcut,flow').split(',');
const flowSizes = (args['flow-sizes'] ?? '128,256').split(',').map(Number);
const flowFrames = Number(args['flow-frames'] ?? 40);
const size = Number(args.size ?? 256);

/** Steps a session to done; returns the step times (sorted), the total and the last event. */
function run(session) {
  const start = performance.now();
  const steps = [];
  let event;
  do {
    const t = performance.now();
    event = session.step();
    steps.push(performance.now() - t);
  } while (!event.done);
  const total = performance.now() - start;
  steps.sort((a, b) => a - b);
  return { total, steps, event, median: steps[Math.floor(steps.length / 2)], max: steps[steps.length - 1] };
}

await init({ module_or_path: readFileSync(new URL('../pkg/texsynth_bg.wasm', import.meta.url)) });

const pad = (v, n) => String(v).padStart(n);
const exemplars = Object.fromEntries(samples.map((name) => [name, Exemplar.fromBytes(readFileSync(new URL(`../www/samples/${name}.png`, import.meta.url)))]));

if (methods.includes('optimization')) {
  console.log(`wasm (Node ${process.version}) texture optimization, ${size}x${size} output, default schedule (r = 0.8, seed 1)`);
  console.log(`${'exemplar'.padEnd(12)} ${'search'.padEnd(12)} ${pad('steps', 6)} ${pad('total ms', 9)} ${pad('median ms', 10)} ${pad('max ms', 10)} ${pad('final energy', 12)}`);
  for (const name of samples) {
    for (const search of searches) {
      // The session is built inside the timed part: planning and pyramids count too.
      const t0 = performance.now();
      const session = new TextureOptimization(exemplars[name], { outputWidth: size, outputHeight: size, search });
      const build = performance.now() - t0;
      const r = run(session);
      console.log(`${name.padEnd(12)} ${search.padEnd(12)} ${pad(r.steps.length, 6)} ${pad((r.total + build).toFixed(1), 9)} ${pad(r.median.toFixed(1), 10)} ${pad(r.max.toFixed(1), 10)} ${pad(r.event.energy.toFixed(6), 12)}`);
      session.free();
    }
  }
}

if (methods.includes('graphcut')) {
  console.log(`\nwasm (Node ${process.version}) graph-cut textures, ${size}x${size} output, default options (seed 1, 24 refinement patches)`);
  console.log(`${'exemplar'.padEnd(12)} ${'placement'.padEnd(13)} ${pad('patches', 8)} ${pad('total ms', 9)} ${pad('median ms', 10)} ${pad('max ms', 10)} ${pad('seam cost', 12)}`);
  for (const name of samples) {
    for (const placement of placements) {
      const t0 = performance.now();
      const session = new GraphcutTextures(exemplars[name], { outputWidth: size, outputHeight: size, placement });
      const build = performance.now() - t0;
      const r = run(session);
      console.log(`${name.padEnd(12)} ${placement.padEnd(13)} ${pad(r.event.patchesPlaced, 8)} ${pad((r.total + build).toFixed(1), 9)} ${pad(r.median.toFixed(1), 10)} ${pad(r.max.toFixed(1), 10)} ${pad(r.event.totalSeamCost.toFixed(1), 12)}`);
      session.free();
    }
  }
}

if (methods.includes('flow')) {
  // Frame rate of the frames after the first (the first is a full multi-level synthesis, timed on
  // its own). Coherence (7x7 patches, exact search; see the README) of every 5th frame is
  // measured outside the timed part and shown relative to the first frame's, beside the naive
  // warp's at the last frame.
  console.log(`\nwasm (Node ${process.version}) flow-guided animation: vortex (strength 2), ${flowFrames} frames, default options (lambda 0.2, sizes [32, 16, 8], 3 iterations); 'step' is the longest step of any frame`);
  console.log(`${'exemplar'.padEnd(12)} ${'frame'.padEnd(8)} ${pad('first ms', 9)} ${pad('ms/frame', 9)} ${pad('max ms', 8)} ${pad('step ms', 8)} ${pad('fps', 6)} ${pad('coherence', 10)} ${pad('mean x1st', 9)} ${pad('max x1st', 9)} ${pad('naive x1st', 10)}`);
  for (const name of samples) {
    for (const size of flowSizes) {
      const anim = new FlowAnimation(exemplars[name], { outputWidth: size, outputHeight: size, frames: flowFrames });
      const rgba = new Uint8ClampedArray(size * size * 4);
      const frameTimes = [];
      const coherences = [];
      let first = 0;
      let longestStep = 0;
      let t = performance.now();
      while (!anim.done) {
        const before = performance.now();
        const event = anim.step();
        longestStep = Math.max(longestStep, performance.now() - before);
        if (event.frameFinished) {
          const now = performance.now();
          if (event.frame === 0) first = now - t;
          else frameTimes.push(now - t);
          if (event.frame % 5 === 0 || event.done) {
            anim.renderInto(rgba);
            coherences.push(measureQuality(exemplars[name], rgba, size, size).coherence);
          }
          t = performance.now();
        }
      }
      anim.renderNaiveInto(rgba);
      const naive = measureQuality(exemplars[name], rgba, size, size).coherence;
      const mean = frameTimes.reduce((a, b) => a + b, 0) / frameTimes.length;
      const later = coherences.slice(1);
      const rel = (c) => (c / coherences[0]).toFixed(2);
      console.log(`${name.padEnd(12)} ${`${size}x${size}`.padEnd(8)} ${pad(first.toFixed(0), 9)} ${pad(mean.toFixed(1), 9)} ${pad(Math.max(...frameTimes).toFixed(1), 8)} ${pad(longestStep.toFixed(0), 8)} ${pad((1000 / mean).toFixed(1), 6)} ${pad(coherences[0].toExponential(2), 10)} ${pad(rel(later.reduce((a, b) => a + b, 0) / later.length), 9)} ${pad(rel(Math.max(...later)), 9)} ${pad(rel(naive), 10)}`);
      anim.free();
    }
  }
}
