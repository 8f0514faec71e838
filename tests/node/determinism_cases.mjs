// The determinism cases, the same names, samples and options as tests/determinism_hashes.rs
// (the native side): keep the two lists in step. Small enough to run in a few seconds.
import { api, sampleBytes } from './fixtures.mjs';

const small = { outputWidth: 48, outputHeight: 48, seed: 3, neighbourhoodSizes: [16, 8], iterations: 3 };
export const CASES = [
  ...['gravel_64', 'tiles_64', 'brick_64', 'grass_64'].map((s) => ({ name: `optimization/${s}`, kind: 'TextureOptimization', sample: s, options: small })),
  // The default schedule and IRLS weights (r = 0.8, powf in every E-step).
  ...['carpet_64', 'squares_64'].map((s) => ({ name: `optimization-default/${s}`, kind: 'TextureOptimization', sample: s, options: { outputWidth: 96, outputHeight: 96, seed: 3 } })),
  { name: 'optimization-haar/sand_64', kind: 'TextureOptimization', sample: 'sand_64', options: { ...small, energy: 'haar' } },
  ...['gravel_64', 'tiles_64'].map((s) => ({ name: `graphcut/${s}`, kind: 'GraphcutTextures', sample: s, options: { outputWidth: 96, outputHeight: 96, seed: 3, refinementPatches: 4 } })),
  { name: 'features/paving_64', kind: 'FeatureSynthesis', sample: 'paving_64', options: { outputWidth: 96, outputHeight: 96, patchSize: 32, seed: 3 } },
  { name: 'flow/gravel_64', kind: 'FlowAnimation', sample: 'gravel_64', options: { outputWidth: 48, outputHeight: 48, frames: 3, seed: 3 } },
  { name: 'layers/brick_64', kind: 'LayerDesign', sample: 'brick_64', options: { outputWidth: 96, outputHeight: 96, patchSize: 16, seed: 3 }, deformations: [{ rotate: 30 }] },
];

/** 32-bit FNV-1a as 8 hex digits, as the native example computes it. */
export function fnv1a(bytes) {
  let h = 0x811c9dc5;
  for (const b of bytes) {
    h ^= b;
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h.toString(16).padStart(8, '0');
}

/** Runs a case to the end in this thread with the module `lib`; returns its RGBA output. */
export function runCase({ kind, sample, options, deformations }, lib = api) {
  const api = lib;
  const exemplar = api.Exemplar.fromBytes(sampleBytes(sample));
  let session;
  if (kind === 'LayerDesign') {
    session = new api.LayerDesign(options);
    session.addLayer(exemplar, deformations);
  } else {
    session = new api[kind](exemplar, options);
  }
  while (!session.done) session.step();
  const out = new Uint8ClampedArray(session.width * session.height * 4);
  session.renderInto(out);
  session.free();
  exemplar.free();
  return out;
}
