// The sessions the speed benchmarks time, one per method name, so that bench-scaling.mjs and
// bench-ab.mjs time the same thing: each method with default options at a square output size,
// within a memory budget that lets 4096x4096 run.

/** The method names, in the order the tables list them. */
export const METHODS = ['optimization', 'graphcut', 'subpatch', 'features', 'flow'];

/**
 * A new session of `method` (one of METHODS) from `exemplar` to a `size` x `size` output, with the
 * package `lib`; flow animation runs `flowFrames` frames. Returns null for an unknown method.
 */
export function makeSession(lib, method, exemplar, size, flowFrames) {
  const output = { outputWidth: size, outputHeight: size, memoryBudgetMiB: 3584 };
  const make = {
    optimization: () => new lib.TextureOptimization(exemplar, output),
    graphcut: () => new lib.GraphcutTextures(exemplar, { ...output, placement: 'entire-patch' }),
    subpatch: () => new lib.GraphcutTextures(exemplar, { ...output, placement: 'sub-patch' }),
    features: () => new lib.FeatureSynthesis(exemplar, output),
    flow: () => new lib.FlowAnimation(exemplar, { ...output, frames: flowFrames }),
  }[method];
  return make ? make() : null;
}
