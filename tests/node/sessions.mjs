// THE table of what JavaScript can create: every session type and one-call function of the
// package, how to make a tiny one from an options object (and optionally the caller's exemplar or
// clip, `input`, which the caller then owns), how to drive it a little, and each
// option it reads with the kind of value it takes. The bad-input corpus, the leak test and the
// determinism tests are all generated from it, so a new option joins every one of them with one
// line here (and a new session type with one entry).
import { api, render, tinyClip, tinyExemplar } from './fixtures.mjs';

// Kinds of option value; bad_values.mjs holds the wrong values tried for each.
export const SIZE = 'size'; // whole pixels from 1
export const COUNT = 'count'; // whole number from 0
export const SEED = 'seed';
export const REAL = 'real'; // any finite number
export const BOOL = 'bool';
export const BUDGET = 'budget'; // memoryBudgetMiB
export const COUNTS = 'counts'; // array of whole numbers
export const REALS = 'reals'; // array of finite numbers
export const enumOf = (...names) => ({ enum: names });
export const special = (values) => ({ special: values });

const ex = (side = 32) => tinyExemplar(side);

/** The tiny defaults with the caller's options over them; anything but a plain object is passed
 * as it is, so that the corpus can hand a session a number or a string for its options. */
const over = (defaults, o) =>
  o === undefined || (o !== null && typeof o === 'object' && !Array.isArray(o)) ? { ...defaults, ...o } : o;

/** Steps a session up to `steps` times (fewer if it finishes), then renders it. */
export function exercise(session, steps = 3) {
  for (let i = 0; i < steps && !session.done; i++) session.step();
  return render(session);
}

/** A small 'brushed' mask: a square in the middle of a `w` x `h` reference. */
const squareMask = (w, h) => {
  const mask = new Uint8Array(w * h);
  for (let y = h / 4; y < (3 * h) / 4; y++) for (let x = w / 4; x < (3 * w) / 4; x++) mask[y * w + x] = 1;
  return mask;
};

/** What `make(options, input)` of a session type takes as `input`: a clip for video, else an exemplar. */
export const inputFor = (kind) => (kind === 'VideoTextures' ? tinyClip() : ex());

export const SESSIONS = {
  TextureOptimization: {
    make: (o, input = ex()) => new api.TextureOptimization(input, over({ outputWidth: 24, outputHeight: 24, neighbourhoodSizes: [8, 4], iterations: 2 }, o)),
    options: {
      outputWidth: SIZE, outputHeight: SIZE, seed: SEED, levels: COUNT, neighbourhoodSizes: COUNTS,
      iterations: COUNT, r: REAL, mu: REAL, mStepMu: REAL, search: enumOf('patchmatch', 'kmeans-tree', 'exact'),
      tileable: BOOL, completeness: REAL, histogramMatching: REAL,
      energy: enumOf('pixels', 'haar', 'daubechies'), waveletDetailWeight: REAL, start: enumOf('graphcut', 'patches'), channelWeights: REALS,
      memoryBudgetMiB: BUDGET,
    },
  },
  FlowAnimation: {
    make: (o, input = ex()) => new api.FlowAnimation(input, over({ outputWidth: 16, outputHeight: 16, frames: 2, frameSizes: [8], frameIterations: 1 }, o)),
    options: {
      outputWidth: SIZE, outputHeight: SIZE, frames: COUNT, lambda: REAL, frameSizes: COUNTS,
      frameIterations: COUNT, seed: SEED, search: enumOf('patchmatch', 'kmeans-tree', 'exact'), r: REAL,
      tileable: BOOL, histogramMatching: REAL, subPixel: BOOL, memoryBudgetMiB: BUDGET,
      flow: special([
        ['vortex', 'flow'], [{}, 'flow.type'], [{ type: 'nope' }, 'flow.type'], [{ type: 'vortex', bogus: 1 }, 'bogus'],
        [{ type: 'vortex', strength: NaN }, 'strength'], [{ type: 'sink', centreX: '0.5' }, 'centreX'],
        [{ components: 3 }, 'flow.components'], [{ components: [{ type: 'shear' }, 7] }, 'options'],
        [{ components: [] }, { either: 'flow' }], [{ type: 'vortex', strength: 1e30 }, { either: 'strength' }],
        [{ type: 'vortex', period: 0 }, { either: 'period' }], [{ type: 'translation', angle: -1e300 }, { either: 'angle' }],
        [new Float32Array(5), 'flow field'], [[new Float32Array(16 * 16 * 2), new Float32Array(3)], 'flow field'],
        [[], { either: 'flow' }], [[1, 2], 'flow'], [new Float32Array(16 * 16 * 2).fill(NaN), { either: 'flow' }],
        [new Float32Array(16 * 16 * 2).fill(1e30), { either: 'flow' }],
      ]),
    },
  },
  GraphcutTextures: {
    make: (o, input = ex()) => new api.GraphcutTextures(input, over({ outputWidth: 40, outputHeight: 40, refinementPatches: 1 }, o)),
    options: {
      outputWidth: SIZE, outputHeight: SIZE, seed: SEED, placement: enumOf('random', 'entire-patch', 'sub-patch'),
      k: REAL, errorRegion: COUNT, refinementPatches: COUNT, gradientCost: BOOL,
      blend: enumOf('none', 'feather', 'spline'), rotate: BOOL, mirror: BOOL, scales: REALS, perspective: BOOL,
      tileable: BOOL, memoryBudgetMiB: BUDGET,
    },
  },
  Inpainting: {
    make: (o, input = ex()) => new api.Inpainting(input, squareMask(input.width, input.height), over({ patchSize: 8, neighbourhoodSizes: [8, 4], iterations: 1 }, o)),
    options: {
      seed: SEED, patchSize: COUNT, k: REAL, levels: COUNT, neighbourhoodSizes: COUNTS, iterations: COUNT, r: REAL,
      search: enumOf('patchmatch', 'kmeans-tree', 'exact'), histogramMatching: REAL, completeness: REAL,
      optimize: BOOL, memoryBudgetMiB: BUDGET,
    },
  },
  VideoTextures: {
    make: (o, input = tinyClip()) => new api.VideoTextures(input, over({ transitionWindow: 4, refinementPatches: 0 }, o)),
    options: {
      mode: enumOf('loop', 'offsets', 'extend'), outputWidth: SIZE, outputHeight: SIZE, outputFrames: SIZE,
      fixedFrames: COUNT, transitionWindow: COUNT, transitions: COUNT, blend: enumOf('none', 'feather'), placement: enumOf('random', 'entire-patch', 'sub-patch', 'matching'), seed: SEED, k: REAL,
      refinementPatches: COUNT, gradientCost: BOOL, memoryBudgetMiB: BUDGET,
    },
  },
  TileableTexture: {
    make: (o, input = ex()) => new api.TileableTexture(input, o),
    options: { overlapX: COUNT, overlapY: COUNT, memoryBudgetMiB: BUDGET },
  },
  TextureBrush: {
    make: (o, input = ex()) => new api.TextureBrush(input, over({ margin: 4 }, o)),
    exercise: (brush) => {
      const reference = ex();
      brush.stroke(reference, squareMask(32, 32), 3, -2);
      reference.free();
      brush.undo();
      return render(brush);
    },
    options: { nu: REAL, k1: REAL, k2: REAL, margin: COUNT, poisson: BOOL, memoryBudgetMiB: BUDGET },
  },
  LayerDesign: {
    make: (o, input) => {
      const design = new api.LayerDesign(over({ outputWidth: 24, outputHeight: 24, patchSize: 8 }, o));
      const layer = input ?? ex();
      design.addLayer(layer, [{ rotate: 90 }]);
      if (!input) layer.free();
      return design;
    },
    options: {
      outputWidth: SIZE, outputHeight: SIZE, patchSize: COUNT, overlap: COUNT, search: enumOf('qtp', 'exhaustive'),
      keep: COUNT, placement: enumOf('logistic', 'random', 'best'), tolerance: REAL, seed: SEED, memoryBudgetMiB: BUDGET,
    },
  },
  FeatureSynthesis: {
    make: (o, input = ex()) => new api.FeatureSynthesis(input, over({ outputWidth: 32, outputHeight: 32, patchSize: 16 }, o)),
    options: {
      outputWidth: SIZE, outputHeight: SIZE, placement: enumOf('graphcut', 'scan'), seamFeatureWeight: REAL,
      patchSize: SIZE, overlap: SIZE, featureWeight: REAL, warp: BOOL, tolerance: REAL, featureCandidates: SIZE,
      features: enumOf('edges', 'ridges', 'both'), threshold: REAL, alpha: REAL, seed: SEED, memoryBudgetMiB: BUDGET,
      extraInputs: special([
        ['mirror', 'extraInputs'], [['rotate45'], 'extraInputs'], [[3], 'extraInputs'], [[], 'ok'],
      ]),
      featureMask: special([
        [new Uint8Array(5), 'featureMask'], ['mask', 'featureMask'], [new Uint8Array(32 * 32).fill(1), 'ok'],
      ]),
    },
  },
  GraphcutMerge: {
    make: (o, input) => {
      const merge = new api.GraphcutMerge(over({ outputWidth: 24, outputHeight: 24, gradientCost: true }, o));
      const source = input ?? ex();
      merge.addSource(source, 0, 0);
      // The second source inside the output whatever size the corpus gives it.
      const inside = (v, at) => (Number.isInteger(v) && v > 0 ? Math.min(at, v - 1) : at);
      merge.addSource(source, inside(o?.outputWidth, 10), inside(o?.outputHeight, 6));
      if (!input) source.free();
      return merge;
    },
    options: { outputWidth: SIZE, outputHeight: SIZE, gradientCost: BOOL },
  },
  // One-call functions that take an options object: the same corpus applies.
  makeTileable: {
    make: (o) => api.makeTileable(ex(), o),
    options: { overlapX: COUNT, overlapY: COUNT, memoryBudgetMiB: BUDGET },
  },
  detectFeatures: {
    make: (o, input = ex()) => api.detectFeatures(input, o),
    options: { features: enumOf('edges', 'ridges', 'both'), threshold: REAL, alpha: REAL },
  },
  measureBrokenFeatures: {
    make: (o) => {
      const e = ex();
      return api.measureBrokenFeatures(e, e.toRgba(), 32, 32, o);
    },
    options: { features: enumOf('edges', 'ridges', 'both'), threshold: REAL, alpha: REAL },
  },
  deformationSet: {
    make: (o) => api.deformationSet(ex(), o),
    options: {
      mirror: BOOL, flip: BOOL,
      ...Object.fromEntries(['rotation', 'scale', 'shift'].map((name) => [name, special([
        [5, name], [{ from: 0, to: 1 }, name], [{ from: NaN, to: 1, step: 1 }, 'from'],
        [{ from: 0, to: 1, step: 0 }, { either: 'step' }], [{ from: 0, to: 1, step: -1 }, { either: 'step' }],
        [{ from: 0, to: 1e9, step: 1e-9 }, { either: name }], [{ from: 1, to: 0, step: 1 }, { either: name }],
        [{ from: 0, to: 1, step: 1, by: 2 }, 'by'],
      ])])),
    },
  },
};
