// The sessions the speed benchmarks time, one per method name, so that bench-scaling.mjs,
// bench-ab.mjs and bench-threads.mjs time the same thing: each method with default options at a
// square output size, within a memory budget that lets 4096x4096 run.

/** The method names, in the order the tables list them. */
export const METHODS = ['optimization', 'graphcut', 'subpatch', 'features', 'flow'];

/**
 * The class name and options of `method`'s session (one of METHODS) to a `size` x `size`
 * output; flow animation runs `flowFrames` frames. Returns null for an unknown method.
 */
export function sessionSpec(method, size, flowFrames) {
  const output = { outputWidth: size, outputHeight: size, memoryBudgetMiB: 3584 };
  return {
    optimization: { kind: 'TextureOptimization', options: output },
    graphcut: { kind: 'GraphcutTextures', options: { ...output, placement: 'entire-patch' } },
    subpatch: { kind: 'GraphcutTextures', options: { ...output, placement: 'sub-patch' } },
    features: { kind: 'FeatureSynthesis', options: output },
    flow: { kind: 'FlowAnimation', options: { ...output, frames: flowFrames } },
  }[method] ?? null;
}

/**
 * A new session of `method` (one of METHODS) from `exemplar` to a `size` x `size` output, with the
 * package `lib`; flow animation runs `flowFrames` frames. Returns null for an unknown method.
 */
export function makeSession(lib, method, exemplar, size, flowFrames) {
  const spec = sessionSpec(method, size, flowFrames);
  return spec ? new lib[spec.kind](exemplar, spec.options) : null;
}
