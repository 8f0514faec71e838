// Typed declarations of texsynth-wasm (every entry point: node, browser, web). Hand-written over
// the wasm-bindgen output (texsynth.d.ts, where options and events are `any` because the bindings
// read plain JS objects by hand): the same classes and functions with typed option objects, typed
// events and the iteration helpers. The test tests/e2e/npm_pack.test.mjs type-checks an example
// that uses every export, and checks that these declarations cover every member of the generated
// ones, so a method added in Rust and missing here fails the test.

/** Anything `init()` can load the module from. */
export type InitInput = RequestInfo | URL | Response | BufferSource | WebAssembly.Module;

/**
 * Loads the wasm module (a no-op when it is loaded: the `node` and `browser` entry points load it
 * at import). `input`: a URL or path, a `Request`, a `Response` or a promise of one, bytes, or a
 * `WebAssembly.Module`; default: `texsynth_bg.wasm` beside the module.
 */
export default function init(input?: InitInput | Promise<InitInput> | { module_or_path: InitInput | Promise<InitInput> }): Promise<unknown>;
export { init };
/** Synchronous load from bytes or a compiled `WebAssembly.Module`. */
export function initSync(input: BufferSource | WebAssembly.Module | { module: BufferSource | WebAssembly.Module }): unknown;
/** Resolves on the next turn of the event loop (what `run()` awaits between steps). */
export function yieldToEventLoop(): Promise<void>;

/**
 * Every error the library throws is a plain JS `Error` whose message names the problem (the
 * option, the value, the size): invalid options, undecodable bytes, wrong buffer lengths.
 * `run()` rejects with the `AbortSignal`'s reason (a `DOMException` named 'AbortError' by default).
 */
export type TexsynthError = Error;

/** Pixels to write into: `width * height * 4` RGBA8 bytes, e.g. `ImageData.data`. */
export type RgbaTarget = Uint8ClampedArray;
type Bytes = Uint8Array | Uint8ClampedArray | number[];

/** Options of `run()`. */
export interface RunOptions<E> {
  /** Aborting it stops the run before the next step; `run` rejects with `signal.reason`. */
  signal?: AbortSignal;
  /** Called after every step with the event and the session. */
  onEvent?: (event: E, session: any) => void;
  /** Stop after this many steps (default: until done). */
  maxSteps?: number;
}

/** What every step-driven session has: `for (const event of session)` and `await session.run()`. */
export interface Steppable<E extends { done: boolean }> extends Iterable<E> {
  step(): E;
  readonly done: boolean;
  /**
   * Steps until done, yielding to the event loop between steps; resolves with the last event
   * (null when there was no step to make).
   * @throws the signal's reason when `signal` is aborted.
   */
  run(options?: RunOptions<E>): Promise<E | null>;
}

/** An example texture, decoded and held in wasm memory. */
export class Exemplar {
  private constructor();
  free(): void;
  [Symbol.dispose](): void;
  /** Decodes PNG or JPEG bytes. @throws {TexsynthError} empty or undecodable bytes, too large images. */
  static fromBytes(bytes: Bytes): Exemplar;
  /** Takes the pixels of a canvas `ImageData` (or any `{ data, width, height }` object). */
  static fromImageData(imageData: { data: Bytes; width: number; height: number }): Exemplar;
  /** Takes raw RGBA8 pixels, `width * height * 4` bytes. */
  static fromRgba(rgba: Bytes, width: number, height: number): Exemplar;
  /** Writes the exemplar as RGBA8 into `target` (length `width * height * 4`). */
  renderInto(target: RgbaTarget): void;
  /** The exemplar encoded as PNG. */
  toPng(): Uint8Array;
  /** The exemplar as a new RGBA8 array. */
  toRgba(): Uint8ClampedArray;
  /** A copy whose longer side is at most `maxSide`, shrunk by area averaging (unchanged if already within). */
  resized(maxSide: number): Exemplar;
  /** The `width` x `height` rectangle at (`x`, `y`), which must lie inside, as a new exemplar. */
  cropped(x: number, y: number, width: number, height: number): Exemplar;
  /** 1 (grey), 2 (grey + alpha), 3 (RGB) or 4 (RGBA). */
  readonly channels: number;
  readonly width: number;
  readonly height: number;
}

// ---------------------------------------------------------------- texture optimization

/** Nearest-neighbour search of the M-step. */
export type Search = 'patchmatch' | 'kmeans-tree' | 'exact';

/** Options of `TextureOptimization` (Kwatra et al. 2005). Unknown keys and impossible values throw. */
export interface TextureOptimizationOptions {
  /** Memory budget of the session in MiB (16 to 3584, default 1024): the constructor refuses a size whose estimated working set is larger. */
  memoryBudgetMiB?: number;
  /** Output width in pixels. Default: 256. */
  outputWidth?: number;
  /** Output height in pixels. Default: 256. */
  outputHeight?: number;
  /** Random seed; same seed, options and input give the same output. Default: 1. */
  seed?: number;
  /** Resolution levels (octaves) of the schedule. Default: 3. */
  levels?: number;
  /** Neighbourhood sizes, largest first; sizes that do not fit a level's exemplar are skipped. Default: [32, 16, 8]. */
  neighbourhoodSizes?: number[];
  /** EM iterations per level and size at most (a level also ends when no match changes). Default: 5. */
  iterations?: number;
  /** Robust IRLS exponent (2 is least squares). Default: 0.8 (the paper's). */
  r?: number;
  /** Weight of the gradient energy (the paper uses 10). Default: 0 (off). */
  mu?: number;
  /** The M-step's own gradient weight, where it should differ from `mu` (0..1000; not in the paper). At mu = 10 the search matches by gradient almost alone and outputs drift into colour blotches; 1 keeps a search that sees colour. Default: `mu` up to 1, then 1; set it to `mu` for the paper's single energy. */
  mStepMu?: number;
  /** Nearest-neighbour search. Default: 'patchmatch'. */
  search?: Search;
  /** Make the output tile seamlessly. Default: false. */
  tileable?: boolean;
  /** Weight of the occurrence penalty that makes the output use all of the exemplar (0: the paper's M-step). Default: 1. */
  completeness?: number;
  /** How far the output's colour histogram is matched to the exemplar's (0..1). Default: 1. */
  histogramMatching?: number;
  /** Texture energy: pixels, or the wavelet energy of Shen et al. 2009. Default: 'pixels'. */
  energy?: 'pixels' | 'haar' | 'daubechies';
  /** Weight of the wavelet detail bands (with a wavelet `energy`). Default: 4. */
  waveletDetailWeight?: number;
  /** How the coarsest level starts: a graph-cut synthesis at its size, which keeps lattices and large elements whole, or random exemplar patches (closer to the paper's random start). Default: 'graphcut'. */
  start?: 'graphcut' | 'patches';
}

/** What one `TextureOptimization.step()` did. */
export interface TextureOptimizationEvent {
  /** 'part': a step inside an iteration (large outputs split iterations so no step blocks long). */
  kind: 'level' | 'iteration' | 'part' | 'done';
  done: boolean;
  level: number;
  levelCount: number;
  octave: number;
  /** 2^octave: the level is 1/scale of the output size. */
  scale: number;
  neighbourhoodSize: number;
  iteration: number;
  /** The pixel term ||x_p - z_p||^r, normalised, whatever the `energy` option. */
  energy: number;
  /** What the M-step minimised (equal to `energy` for 'pixels'). */
  matchEnergy: number;
  /** Matches that changed in this iteration. */
  changed: number;
  totalIterations: number;
  /** Conjugate-gradient iterations of the gradient solve. */
  solverIterations: number;
  /** Where the step stopped: making the coarsest level's graph-cut start, the M-step on a level's up-sampled output, the E-step or the M-step. */
  phase: 'start' | 'first-match' | 'e-step' | 'm-step';
  /** Share of the iteration done, 0 to 1 (1 for a whole iteration). */
  progress: number;
}

/** One planned level of a `TextureOptimization`. */
export interface ScheduleLevel {
  octave: number; scale: number; neighbourhoodSize: number; spacing: number;
  outputWidth: number; outputHeight: number; exemplarWidth: number; exemplarHeight: number;
}

/** The neighbourhood grid X† of the level last iterated and the chosen exemplar corners z_p. */
export interface NeighbourhoodField {
  columns: number[] | Uint32Array; rows: number[] | Uint32Array; neighbourhoodSize: number;
  levelWidth: number; levelHeight: number; exemplarWidth: number; exemplarHeight: number;
  /** x, y pairs, row by row. */
  matches: number[] | Uint32Array | Int32Array;
  /** ||x_p - z_p|| per node after the last M-step (NaN before the level's first). */
  distances: Float32Array;
  /** The next E-step's IRLS weight ||x_p - z_p||^(r-2) per node (NaN before the first M-step). */
  weights: Float32Array;
  /** The robust exponent r. */
  r: number;
}

/** A texture-optimisation run (Kwatra et al. 2005) you advance with `step()`. */
export class TextureOptimization implements Steppable<TextureOptimizationEvent> {
  /** @throws {TexsynthError} unknown option keys, impossible values (named in the message). */
  constructor(exemplar: Exemplar, options?: TextureOptimizationOptions);
  /** The estimated peak working set in bytes (what the memory budget is checked against). */
  readonly memoryEstimate: number;
  free(): void;
  [Symbol.dispose](): void;
  [Symbol.iterator](): Iterator<TextureOptimizationEvent>;
  run(options?: RunOptions<TextureOptimizationEvent>): Promise<TextureOptimizationEvent | null>;
  /** Runs one EM iteration. */
  step(): TextureOptimizationEvent;
  /** Writes the current output as RGBA8 into `target` (`width * height * 4` long). */
  renderInto(target: RgbaTarget): void;
  /** The colour-coded offset map (red = exemplar x, green = exemplar y). */
  renderOffsetMap(target: RgbaTarget): void;
  /** Normalised energy after every iteration so far. */
  energyHistory(): Float64Array;
  /** The level index of every point of `energyHistory()`. */
  historyLevels(): Uint32Array;
  /** The planned levels, coarsest first. */
  schedule(): ScheduleLevel[];
  /** The neighbourhood grid of the level last iterated; null before the first step. */
  field(): NeighbourhoodField | null;
  /**
   * Step anatomy: with `true` every step ends after one half of an EM iteration (a part event
   * with phase 'first-match' or 'e-step', then the iteration's event after its M-step); the
   * output is the same either way.
   */
  setHalfSteps(on: boolean): void;
  /**
   * Soft constraints (section 4): RGBA desired colours at output size whose alpha is the mask;
   * `lambda` (0 to 1e6) relative to the texture (1 = half way).
   */
  setConstraints(rgba: Bytes, lambda: number): void;
  /** Removes the soft constraints. */
  clearConstraints(): void;
  /** Mean squared difference to the constraint colours over the masked pixels (0 without). */
  readonly constraintEnergy: number;
  readonly done: boolean;
  readonly energy: 'pixels' | 'haar' | 'daubechies';
  readonly search: Search;
  readonly width: number;
  readonly height: number;
}

// ---------------------------------------------------------------- graph-cut textures

/** Options of `GraphcutTextures` (Kwatra et al. 2003). Unknown keys and impossible values throw. */
export interface GraphcutTexturesOptions {
  /** Memory budget of the session in MiB (16 to 3584, default 1024): the constructor refuses a size whose estimated working set is larger. */
  memoryBudgetMiB?: number;
  /** Default: 256. */
  outputWidth?: number;
  /** Default: 256. */
  outputHeight?: number;
  /** Default: 1. */
  seed?: number;
  /** Patch placement (section 3.2). Default: 'random'. */
  placement?: 'random' | 'entire-patch' | 'sub-patch';
  /** Offsets are drawn with probability exp(-C / (k sigma^2)). Default: 0.01. */
  k?: number;
  /** Side of the error region in pixels; 0 is a third of the exemplar's side. Default: 0. */
  errorRegion?: number;
  /** Patches placed after the output is covered. Default: 24. */
  refinementPatches?: number;
  /** Seam cost M' of eq. 5 (favours edges) instead of M of eq. 1. Default: false. */
  gradientCost?: boolean;
  /** Blending across seams. Default: 'none'. */
  blend?: 'none' | 'feather' | 'spline';
  /** Also take patches from the exemplar rotated by 90, 180, 270 degrees. Default: false. */
  rotate?: boolean;
  /** Also take patches from the mirrored exemplar. Default: false. */
  mirror?: boolean;
  /** Also take patches from the exemplar scaled by these factors. Default: []. */
  scales?: number[];
  /** With scales: smaller scales towards the top. Default: false. */
  perspective?: boolean;
  /** Make the output tile seamlessly. Default: false. */
  tileable?: boolean;
}

export interface Rect { x: number; y: number; width: number; height: number }

/** What one `GraphcutTextures.step()` did. */
export interface GraphcutTexturesEvent {
  kind: 'placed' | 'done';
  done: boolean;
  patch: { source: number; offsetX: number; offsetY: number; windowX: number; windowY: number } | null;
  rect: Rect | null;
  region: Rect | null;
  pixelsTaken: number;
  cutCost: number;
  /** Whether every output pixel has been covered. */
  covered: boolean;
  totalSeamCost: number;
  patchesPlaced: number;
}

/** A graph-cut texture synthesis (Kwatra et al. 2003) you advance with `step()`. */
export class GraphcutTextures implements Steppable<GraphcutTexturesEvent> {
  /** @throws {TexsynthError} unknown option keys, impossible values. */
  constructor(exemplar: Exemplar, options?: GraphcutTexturesOptions);
  /** The estimated peak working set in bytes (what the memory budget is checked against). */
  readonly memoryEstimate: number;
  /**
   * The broken-feature count on the output's carried feature map (each made pixel carries the
   * curve of the exemplar pixel it shows, from `featureMask`, one byte per exemplar pixel:
   * `FeatureMap.toMask()`): curve ends per 1000 curve pixels above the mask's own, the curves
   * seams cut. Refused for a session with deformed sources.
   */
  carriedBrokenFeatures(featureMask: Bytes): number;
  /**
   * `carriedBrokenFeatures` with the curves of `map` (the exemplar's map as edited) instead of
   * its mask: in a worker, pass the worker's own FeatureMap and a photo's map stays there.
   */
  carriedBrokenFeaturesOf(map: FeatureMap): number;
  free(): void;
  [Symbol.dispose](): void;
  [Symbol.iterator](): Iterator<GraphcutTexturesEvent>;
  run(options?: RunOptions<GraphcutTexturesEvent>): Promise<GraphcutTexturesEvent | null>;
  /** Places one patch. */
  step(): GraphcutTexturesEvent;
  renderInto(target: RgbaTarget): void;
  /** The label map: every patch in its own colour. */
  renderLabels(target: RgbaTarget): void;
  /** The per-pixel seam cost as a heat map. */
  renderSeamCost(target: RgbaTarget): void;
  /** Seam pixels opaque red, the rest transparent. */
  renderSeams(target: RgbaTarget): void;
  /** The error region of the last placement, or null. */
  errorRegion(): Rect | null;
  /** Names of the sources patches come from ("exemplar", "rotate 90", "scale 0.5", ...). */
  sources(): string[];
  /** Records each placement's cost surface and graph (for `placementCosts`, `placementGraph`). */
  setAnatomy(on: boolean): void;
  /** The last placement's cost surface C(t) and eq. 3's probabilities; null unless recorded. */
  placementCosts(): PlacementCosts | null;
  /** The last placement's seam graph per pixel of the patch; null unless recorded. */
  placementGraph(): PlacementGraph | null;
  readonly done: boolean;
  readonly width: number;
  readonly height: number;
}

/** C(t) over the candidate offsets of one placement (offset of cell (i, j): (x + i, y + j)). */
export interface PlacementCosts {
  x: number; y: number; width: number; height: number;
  /** Area-normalised SSD (eq. 2 / 4); Infinity where no unused candidate is. */
  cost: Float32Array;
  /** exp(-C / (k sigma^2)) normalised to sum 1 (eq. 3). */
  probability: Float32Array;
  /** Grid cell of the offset drawn (-1 when none). */
  chosenX: number; chosenY: number;
  /** k sigma^2. */
  temperature: number;
}

/** The seam graph of one placement per pixel of the patch's box (origin x, y). */
export interface PlacementGraph {
  x: number; y: number; width: number; height: number;
  /** 0 outside, 1 uncovered (takes the patch, no node), 2 free node, 3 held to the old output, 4 held to the patch. */
  kind: Uint8Array;
  /** Arc capacity to the right / lower neighbour (NaN: no arc). */
  right: Float32Array; down: Float32Array;
  /** Old seam cost there (NaN: none). */
  oldRight: Float32Array; oldDown: Float32Array;
  /** 1 where the pixel took the new patch. */
  taken: Uint8Array;
}

/** What one `GraphcutMerge.step()` did. */
export interface GraphcutMergeEvent {
  kind: 'merged' | 'done';
  done: boolean;
  /** Index of the source laid down, or null. */
  source: number | null;
  cutCost: number;
}

/** Interactive merging of up to 8 sources (Kwatra et al. 2003, section 6). */
export class GraphcutMerge implements Steppable<GraphcutMergeEvent> {
  /** @param gradientCost seam cost M' (eq. 5). Default: true. */
  constructor(width: number, height: number, gradientCost?: boolean | null);
  free(): void;
  [Symbol.dispose](): void;
  [Symbol.iterator](): Iterator<GraphcutMergeEvent>;
  run(options?: RunOptions<GraphcutMergeEvent>): Promise<GraphcutMergeEvent | null>;
  /** Adds a source with its top-left corner at (x, y) of the output; returns its index. */
  addSource(exemplar: Exemplar, x: number, y: number): number;
  /** One byte per output pixel: 0 free, k = must come from source k - 1. */
  setConstraints(mask: Bytes): void;
  step(): GraphcutMergeEvent;
  renderInto(target: RgbaTarget): void;
  renderSeams(target: RgbaTarget): void;
  renderSources(target: RgbaTarget): void;
  /** Records each step's seam graph for `placementGraph()` (off by default). */
  setAnatomy(on: boolean): void;
  /** The last step's seam graph, painted pixels as its constraint nodes (kind 3: held to the
   * composite so far; 4: to the new source); null unless `setAnatomy(true)` came first. */
  placementGraph(): PlacementGraph | null;
  readonly done: boolean;
  readonly width: number;
  readonly height: number;
}

// ---------------------------------------------------------------- flow animation

export type FlowKind = 'sink' | 'source' | 'vortex' | 'shear' | 'translation';

/** One flow generator. */
export interface FlowComponent {
  type: FlowKind;
  /** Pixels per frame at half the frame's shorter side. Default: 1 (2 for the animation's default vortex). */
  strength?: number;
  /** Centre, 0..1 of the width. Default: 0.5. */
  centerX?: number;
  /** Centre, 0..1 of the height. Default: 0.5. */
  centerY?: number;
  /** Degrees (translation and shear). Default: 0. */
  angle?: number;
  /** Frames; the strength oscillates with this period. Default: 0 (constant). */
  period?: number;
  /** Degrees per frame the angle turns. Default: 0. */
  turn?: number;
}

/** A flow: a generator, a sum of generators, one field of (vx, vy) per pixel, or one per frame (cycled). */
export type Flow = FlowComponent | { components: FlowComponent[] } | Float32Array | Float32Array[];

/** Options of `FlowAnimation` (Kwatra et al. 2005, section 4.1). */
export interface FlowAnimationOptions {
  /** Memory budget of the session in MiB (16 to 3584, default 1024): the constructor refuses a size whose estimated working set is larger. */
  memoryBudgetMiB?: number;
  /** Default: 128. */
  outputWidth?: number;
  /** Default: 128. */
  outputHeight?: number;
  /** Frames to make. Default: 60. */
  frames?: number;
  /** Weight of the flow (soft-constraint) energy, eq. 3. Default: 0.2. */
  lambda?: number;
  /** Neighbourhood sizes of the frames after the first; sizes that do not fit the exemplar (4 widths) or the frame are skipped; where none fits, the smallest at most half the exemplar. Default: [32, 16, 8]. */
  frameSizes?: number[];
  /** Iterations per size per frame; the last one's M-step only measures its matches (it reports 0 changed). Default: 3. */
  frameIterations?: number;
  /** Default: 1. */
  seed?: number;
  /** Default: 'patchmatch'. */
  search?: Search;
  /** Default: 0.8. */
  r?: number;
  /** Default: false. */
  tileable?: boolean;
  /** As for TextureOptimization. Default: 1. */
  histogramMatching?: number;
  /** Matches at half-pixel precision: flows slower than half a pixel per frame move the texture (with whole-pixel matches they do not), for slightly softer frames. Default: false. */
  subPixel?: boolean;
  /** Default: a vortex of strength 2. */
  flow?: Flow;
}

/** What one `FlowAnimation.step()` did. */
export interface FlowAnimationEvent {
  /** 'part': frames larger than 256x512 split each iteration (and a frame's set-up) over steps of about 60 ms. */
  kind: 'part' | 'iteration' | 'frame' | 'done';
  done: boolean;
  /** A frame was finished by this step: `renderInto` gives it. */
  frameFinished: boolean;
  frame: number;
  iteration: number;
  neighbourhoodSize: number;
  textureEnergy: number;
  flowEnergy: number;
  changed: number;
  totalIterations: number;
  /** The half of the iteration a 'part' step stopped in (a whole iteration: 'm-step'; 'e-step' for a later frame's last iteration at a size, whose M-step only measures). */
  phase: 'first-match' | 'e-step' | 'm-step';
  /** The share of the iteration done, 0 to 1 (1 for a whole iteration). */
  progress: number;
}

/** A flow-guided texture animation you advance with `step()`. */
export class FlowAnimation implements Steppable<FlowAnimationEvent> {
  /** @throws {TexsynthError} unknown keys, bad flow fields (named by pixel or size). */
  constructor(exemplar: Exemplar, options?: FlowAnimationOptions);
  /** The estimated peak working set in bytes (what the memory budget is checked against). */
  readonly memoryEstimate: number;
  free(): void;
  [Symbol.dispose](): void;
  [Symbol.iterator](): Iterator<FlowAnimationEvent>;
  run(options?: RunOptions<FlowAnimationEvent>): Promise<FlowAnimationEvent | null>;
  step(): FlowAnimationEvent;
  renderInto(target: RgbaTarget): void;
  /** The naive baseline: frame 0 warped along the flow, no synthesis. */
  renderNaiveInto(target: RgbaTarget): void;
  /** The field f_t as (vx, vy) per pixel. */
  flowField(t: number): Float32Array;
  textureEnergyHistory(): Float64Array;
  flowEnergyHistory(): Float64Array;
  /**
   * Step anatomy (as `TextureOptimization.setHalfSteps`): every step ends after one half of an
   * EM iteration, in frame 1's synthesis and in every later frame; the frames are the same.
   */
  setHalfSteps(on: boolean): void;
  /**
   * The grid and matches the last step worked on (frame 1's level, then the frame level last
   * iterated); null before the first step and from frame 1's end until frame 2 iterates.
   */
  field(): NeighbourhoodField | null;
  /**
   * The previous frame warped along the flow (eq. 3's constraint target), alpha 0 where the
   * warp had no source. @throws {TexsynthError} during frame 1, which has none.
   */
  renderWarpedInto(target: RgbaTarget): void;
  readonly done: boolean;
  readonly frames: number;
  readonly framesFinished: number;
  readonly width: number;
  readonly height: number;
}

/** The field f_t of a generator for a `width` x `height` frame, (vx, vy) per pixel. */
export function flowField(flow: FlowComponent | { components: FlowComponent[] }, width: number, height: number, t: number): Float32Array;

// ---------------------------------------------------------------- texture design (Shen et al. 2009)

/** One global deformation (exactly one key). */
export type Deformation =
  | { rotate: number }
  | { shift: [number, number] }
  | { mirror: true }
  | { flip: true }
  | { scale: number };

/** Applies global deformations in order. */
export function deformTexture(exemplar: Exemplar, deformations: Deformation[]): Exemplar;

export interface Range { from: number; to: number; step: number }
/** Ranges of `deformationSet`; every key optional. */
export interface DeformationRanges {
  /** Degrees. */
  rotation?: Range;
  scale?: Range;
  /** As a fraction of the size. */
  shift?: Range;
  /** Default: false. */
  mirror?: boolean;
  /** Default: false. */
  flip?: boolean;
}
/** The set of deformed textures, at most 64. */
export function deformationSet(exemplar: Exemplar, ranges: DeformationRanges): { label: string; exemplar: Exemplar }[];

/** Options of `makeTileable` and `TileableSession`. */
export interface TileableOptions {
  /** Memory budget of the session in MiB (16 to 3584, default 1024): the constructor refuses a size whose estimated working set is larger. */
  memoryBudgetMiB?: number;
  /** Default: a sixth of the width, at most 64. */
  overlapX?: number;
  /** Default: a sixth of the height, at most 64. */
  overlapY?: number;
}
export interface TileableResult {
  exemplar: Exemplar; cutX: number; cutY: number; seamCostX: number; seamCostY: number;
  /** RGBA, red on the stitches. */
  seam: Uint8ClampedArray;
}
/** Makes an image cyclic in one call. */
export function makeTileable(exemplar: Exemplar, options?: TileableOptions): TileableResult;

export interface TileableEvent {
  kind: 'stitched' | 'done'; done: boolean; axis: 'x' | 'y'; cut: number; seamCost: number;
}
/** Making an image cyclic one graph cut per step. */
export class TileableSession implements Steppable<TileableEvent> {
  constructor(exemplar: Exemplar, options?: TileableOptions);
  /** The estimated peak working set in bytes (what the memory budget is checked against). */
  readonly memoryEstimate: number;
  free(): void;
  [Symbol.dispose](): void;
  [Symbol.iterator](): Iterator<TileableEvent>;
  run(options?: RunOptions<TileableEvent>): Promise<TileableEvent | null>;
  step(): TileableEvent;
  renderInto(target: RgbaTarget): void;
  /** The finished texture, as `makeTileable` returns it. */
  result(): TileableResult;
  readonly done: boolean;
  readonly width: number;
  readonly height: number;
}

/** Options of `TextureBrush` (local deformation, eqs. 1-3). */
export interface TextureBrushOptions {
  /** Memory budget of the session in MiB (16 to 3584, default 1024): the constructor refuses a size whose estimated working set is larger. */
  memoryBudgetMiB?: number;
  /** Weight of the brushed-pixel term. Default: 1000. */
  nu?: number;
  /** Default: 0.5. */
  k1?: number;
  /** Default: 0.5. */
  k2?: number;
  /** Pixels around the stroke the graph cut may use. Default: 12. */
  margin?: number;
  /** Poisson paste. Default: true. */
  poisson?: boolean;
}
export interface BrushStroke {
  x: number; y: number; width: number; height: number;
  taken: number; energy: number; poissonIterations: number;
}
/** Local deformation with a brush; undoable. */
export class TextureBrush {
  constructor(base: Exemplar, options?: TextureBrushOptions);
  /** The estimated peak working set in bytes (what the memory budget is checked against). */
  readonly memoryEstimate: number;
  free(): void;
  [Symbol.dispose](): void;
  stroke(reference: Exemplar, mask: Bytes, dx: number, dy: number): BrushStroke;
  undo(): boolean;
  renderInto(target: RgbaTarget): void;
  renderLabels(target: RgbaTarget): void;
  toExemplar(): Exemplar;
  readonly undoDepth: number;
  readonly width: number;
  readonly height: number;
}

/** Options of `LayerDesign` (fast layer-based design). */
export interface LayerDesignOptions {
  /** Memory budget of the session in MiB (16 to 3584, default 1024): the constructor refuses a size whose estimated working set is larger. */
  memoryBudgetMiB?: number;
  /** Default: 360. */
  outputWidth?: number;
  /** Default: 360. */
  outputHeight?: number;
  /** 8..256. Default: 32. */
  patchSize?: number;
  /** 1..127. Default: a sixth of patchSize, at least 2. */
  overlap?: number;
  /** Default: 'qtp'. */
  search?: 'qtp' | 'exhaustive';
  /** Candidates kept, 1..256. Default: 32. */
  keep?: number;
  /** Default: 'logistic'. */
  placement?: 'logistic' | 'random' | 'best';
  /** Default: 0.3. */
  tolerance?: number;
  /** Default: 1. */
  seed?: number;
}
export interface LayerDesignEvent {
  kind: 'row' | 'done'; done: boolean; row: number; rows: number; patches: number;
  totalPatches: number; ssd: number; totalSsd: number; positionsSearched: number; pixelsCompared: number;
  /** The most positions one patch's search computed (bounded for layers over 512 a side). */
  largestSearch: number;
}
export class LayerDesign implements Steppable<LayerDesignEvent> {
  constructor(options?: LayerDesignOptions);
  /** The estimated peak working set in bytes (what the memory budget is checked against). */
  readonly memoryEstimate: number;
  free(): void;
  [Symbol.dispose](): void;
  [Symbol.iterator](): Iterator<LayerDesignEvent>;
  run(options?: RunOptions<LayerDesignEvent>): Promise<LayerDesignEvent | null>;
  /** `deformations`: one, a list applied in order, or none (as for `deformTexture`). */
  addLayer(exemplar: Exemplar, deformations?: Deformation | Deformation[] | null): number;
  setLayout(layout: Bytes): void;
  step(): LayerDesignEvent;
  renderInto(target: RgbaTarget): void;
  toExemplar(): Exemplar;
  readonly done: boolean;
  readonly width: number;
  readonly height: number;
}

// ---------------------------------------------------------------- feature-guided synthesis (Wu & Yu 2004)

/** Options of the feature detector (`detectFeatures`, and the same keys in `FeatureSynthesisOptions`). */
export interface DetectFeaturesOptions {
  /** Which curves make the map. Default: 'ridges'. */
  features?: 'ridges' | 'edges' | 'both';
  /** Percentile of the responses above which a pixel is a strong feature, 0.5..0.999. Default: 0.9. */
  threshold?: number;
  /** Weak features: at least alpha times a nearby strong response, 0..1. Default: 0.3. */
  alpha?: number;
}
/** An exemplar's feature map: one-pixel-wide curves with their tangents; paint to correct it. */
export class FeatureMap {
  /** The same as `detectFeatures(exemplar, options)` (so that a worker can make one). */
  constructor(exemplar: Exemplar, options?: DetectFeaturesOptions);
  free(): void;
  [Symbol.dispose](): void;
  /** Paints (`on` true) or erases a disc of `radius` (0..64) pixels at (x, y). */
  paint(x: number, y: number, radius: number, on: boolean): void;
  /** Paints or erases the stroke from (x0, y0) to (x1, y1) with a disc of `radius` pixels, without gaps. */
  paintLine(x0: number, y0: number, x1: number, y1: number, radius: number, on: boolean): void;
  /**
   * The broken-feature count of an RGBA output against this map's exemplar as detected (edits
   * do not move it): `measureBrokenFeatures` with this map's options, without detecting the
   * exemplar again.
   */
  brokenFeatures(rgba: Bytes, width: number, height: number): number;
  /** The curves as RGBA, coloured by orientation bucket. */
  renderInto(target: RgbaTarget): void;
  /** The curves as `width` x `height` RGBA (1..4096), each pixel showing a curve pixel of its footprint if any (a photo's map at its view's size). */
  scaledView(width: number, height: number): Uint8ClampedArray;
  /** One byte per pixel, 1 on a curve: `featureMask` of `FeatureSynthesisOptions`. */
  toMask(): Uint8Array;
  readonly width: number;
  readonly height: number;
  readonly count: number;
}
export function detectFeatures(exemplar: Exemplar, options?: DetectFeaturesOptions): FeatureMap;

/** Options of `FeatureSynthesis`. */
export interface FeatureSynthesisOptions extends DetectFeaturesOptions {
  /** Memory budget of the session in MiB (16 to 3584, default 1024): the constructor refuses a size whose estimated working set is larger. */
  memoryBudgetMiB?: number;
  /** Default: 256. */
  outputWidth?: number;
  /** Default: 256. */
  outputHeight?: number;
  /** 'graphcut': graph-cut placement of the whole exemplar, offsets chosen by colour SSD plus the
   *  feature cost over the band where the patch meets the made output, seams that also pay for
   *  cutting curves (no warp); 'scan': the paper's patches in scan order, warped. Default: 'graphcut'. */
  placement?: 'graphcut' | 'scan';
  /** Graph-cut placement: seam cost per pixel where the two patches disagree on a curve, in units of the exemplar's feature contrast, 0..100. Default: 1. */
  seamFeatureWeight?: number;
  /** 16..128, at most the exemplar's shorter side (scan placement; graph-cut placement's feature band is a quarter of it). Default: 64, or the exemplar's shorter side when smaller (the exemplar needs at least 16x16). */
  patchSize?: number;
  /** Context-region width (scan), or the width of the feature-cost band (graphcut). Default: a quarter of patchSize. */
  overlap?: number;
  /** Weight of the feature cost against the colour SSD, 0..1. Default: 0.5. */
  featureWeight?: number;
  /** Bend each patch onto the context's features (scan placement). Default: true. */
  warp?: boolean;
  /** Scan placement: candidates within (1 + tolerance) of the best are drawn at random, 0..10. Default: 0.1. */
  tolerance?: number;
  /** Best candidates by colour whose feature cost is computed. Default: 64 for graph-cut placement, 256 for scan. */
  featureCandidates?: number;
  /** Deformed copies of the exemplar as extra inputs. Default: []. */
  extraInputs?: Array<'rotate90' | 'rotate180' | 'rotate270' | 'mirror' | 'flip'>;
  /** Default: 1. */
  seed?: number;
  /** An edited feature map, one byte per exemplar pixel (`FeatureMap.toMask()`). Default: detected. */
  featureMask?: Uint8Array;
}
export interface FeatureSynthesisEvent {
  kind: 'patch' | 'done'; done: boolean; patch: number; patches: number; x: number; y: number;
  input: number; sourceX: number; sourceY: number; featureCost: number; colourCost: number;
  contextFeatures: number; correspondences: number; warp: 'none' | 'spline' | 'shepard' | 'skipped';
  /** True when the choice used colour only (no oriented features to match). */
  colourOnly: boolean;
}
/** The last placement: patch, context region, correspondences (x, y, partner x, partner y) and warp grid (dx, dy every 4 px). */
export interface FeaturePlacement { x: number; y: number; size: number; top: number; left: number; pairs: Float32Array; grid: Float32Array }
export class FeatureSynthesis implements Steppable<FeatureSynthesisEvent> {
  constructor(exemplar: Exemplar, options?: FeatureSynthesisOptions);
  /** The estimated peak working set in bytes (what the memory budget is checked against). */
  readonly memoryEstimate: number;
  static withFeatureMap(exemplar: Exemplar, map: FeatureMap, options?: FeatureSynthesisOptions): FeatureSynthesis;
  /** The broken-feature count on the synthesised feature map (see `GraphcutTextures.carriedBrokenFeatures`). */
  carriedBrokenFeatures(): number;
  free(): void;
  [Symbol.dispose](): void;
  [Symbol.iterator](): Iterator<FeatureSynthesisEvent>;
  run(options?: RunOptions<FeatureSynthesisEvent>): Promise<FeatureSynthesisEvent | null>;
  step(): FeatureSynthesisEvent;
  renderInto(target: RgbaTarget): void;
  /** The synthesised feature map, coloured by orientation. */
  renderFeatures(target: RgbaTarget): void;
  /** Graph-cut placement only: records each placement's cost surface (the colour cost, which the feature cost re-ranks) and seam graph. @throws {TexsynthError} with scan placement. */
  setAnatomy(on: boolean): void;
  placementCosts(): PlacementCosts | null;
  placementGraph(): PlacementGraph | null;
  placement(): FeaturePlacement;
  readonly done: boolean;
  readonly width: number;
  readonly height: number;
}
/** A video clip held in wasm memory (RGB frames; alpha is ignored). */
export class VideoClip {
  private constructor();
  /** `frames` RGBA8 frames of `width` x `height`, one after another (`width * height * 4 * frames` bytes). */
  static fromFrames(width: number, height: number, frames: number, rgba: Uint8Array): VideoClip;
  free(): void;
  [Symbol.dispose](): void;
  readonly width: number;
  readonly height: number;
  readonly frames: number;
}

/** Options of `VideoTextures` (graph-cut video textures, Kwatra et al. 2003, section 7). Input and
 *  output together must fit the 256 MiB memory budget, or the constructor throws naming the sizes. */
export interface VideoTexturesOptions {
  /** Memory budget of the session in MiB (16 to 3584, default 1024): the constructor refuses a size whose estimated working set is larger. */
  memoryBudgetMiB?: number;
  /** 'loop' (7.A: best transition by frame-pair SSD, optimal seam surface around it; the output is
   *  the loop), 'offsets' (7.B: the whole clip at random temporal offsets), 'extend' (7.C/7.E:
   *  spatio-temporal patches; frames may be larger). Default: 'loop'. */
  mode?: 'loop' | 'offsets' | 'extend';
  /** Only 'extend' may differ from the clip. Default: the clip's width. */
  outputWidth?: number;
  /** Only 'extend' may differ from the clip. Default: the clip's height. */
  outputHeight?: number;
  /** Not for 'loop' (it chooses the loop length). Default: twice the clip's frames ('offsets'), the clip's ('extend'). */
  outputFrames?: number;
  /** k of 7.D for 'offsets' and 'extend': the first and last k frames fixed, then the first k removed, so the
   *  output loops; 0 = no loop. At most the clip's frame count. Default: 10. */
  fixedFrames?: number;
  /** 'loop': the most frames of the seam window around the transition (shorter clips get at most a sixth of
   *  their frames on either side). Default: 60. */
  transitionWindow?: number;
  /** 'random', or 'matching' (7.C: 3-D FFT SSD of the error region against every translation, eq. 3). Default: 'random'. */
  placement?: 'random' | 'matching';
  /** Default: 1. */
  seed?: number;
  /** k of eq. 3 for matching placement, > 0. Default: 0.01. */
  k?: number;
  /** Patches placed over the worst seams once covered. Default: 2. */
  refinementPatches?: number;
  /** Seam cost M' (eq. 5, divided by the gradients) instead of M. Default: false. */
  gradientCost?: boolean;
}
export interface VideoTexturesEvent {
  done: boolean;
  /** Number of the patch placed by this step, -1 if none. */
  patch: number;
  patches: number;
  /** The patch's offset in output voxels (frames counted after the removal of 7.D's first k). */
  tx: number; ty: number; tt: number;
  voxelsTaken: number;
  cutCost: number;
  covered: boolean;
  /** Fraction of the output covered, 0..1. */
  coverage: number;
  /** The output frame around which the loop closes (centre of 7.A's seam window; the last frame for a 7.D
   *  loop once done), or -1. */
  loopFrame: number;
}
export class VideoTextures implements Steppable<VideoTexturesEvent> {
  constructor(clip: VideoClip, options?: VideoTexturesOptions);
  /** The estimated peak working set in bytes (what the memory budget is checked against). */
  readonly memoryEstimate: number;
  free(): void;
  [Symbol.dispose](): void;
  [Symbol.iterator](): Iterator<VideoTexturesEvent>;
  run(options?: RunOptions<VideoTexturesEvent>): Promise<VideoTexturesEvent | null>;
  step(): VideoTexturesEvent;
  readonly done: boolean;
  readonly width: number;
  readonly height: number;
  /** Output frames (the loop length for 'loop'). */
  readonly frames: number;
  /** Output frame t as opaque RGBA (`width * height * 4`). */
  frameInto(t: number, rgba: Uint8Array): void;
  /** Seam overlay of frame t: spatial seams opaque red, temporal seams translucent yellow, transparent elsewhere. */
  seamsInto(t: number, rgba: Uint8Array): void;
  /** The x-t slice at row y (`width` x `frames`, row t = frame t) with the seams in red (`width * frames * 4`). */
  sliceXtInto(y: number, rgba: Uint8Array): void;
  /** Output frame t as a new RGBA array (for workers: `remote.call('frame', t)`). */
  frame(t: number): Uint8Array;
  /** The seam overlay of frame t as a new RGBA array. */
  seams(t: number): Uint8Array;
  /** The x-t slice at row y as a new RGBA array (`width` x `frames`). */
  sliceXt(y: number): Uint8Array;
  /** The frame the last patch reached into (frame 0 before the first step), as RGBA. */
  renderInto(rgba: Bytes): void;
  /** Records one slice of each placement's cost surface and graph (for `placementCosts`, `placementGraph`). */
  setAnatomy(on: boolean): void;
  /**
   * The last placement's costs over one slice of the 3-D offsets: spatial offsets at the drawn
   * time shift `tt` (axes 'xy'), or temporal offsets as a row (axes 't', 7.B); null unless
   * recorded, and for placements drawn without matching.
   */
  placementCosts(): (PlacementCosts & { axes: 'xy' | 't'; tt: number }) | null;
  /** The last placement's seam graph in one frame of the patch (`frame`: the one with the most overlap); null unless recorded. */
  placementGraph(): (PlacementGraph & { frame: number; firstFrame: number; frames: number }) | null;
}

/** Curve ends per 1000 curve pixels in the output's feature map minus the exemplar's (lower is better). */
export function measureBrokenFeatures(exemplar: Exemplar, rgba: Bytes, width: number, height: number, options?: DetectFeaturesOptions): number;

// ---------------------------------------------------------------- quality

/** Quality of an output against its exemplar; lower is better for all four. */
export interface Quality { coherence: number; completeness: number; histogram: number; flat: number }
export function measureQuality(exemplar: Exemplar, rgba: Bytes, width: number, height: number): Quality;

/** Installs the panic hook (runs by itself at load). */
export function start(): void;
/** The library's version. */
export function version(): string;
