// Typed declarations of texsynth-wasm (every entry point: node, browser, web), over the
// wasm-bindgen output (texsynth.d.ts, where options and events are `any` because the bindings
// read plain JS objects): the classes and functions with typed option objects, typed events and
// the iteration helpers. The option objects and events are not written here: schema.d.ts is
// generated from the tables the bindings read and build them with (scripts/make-typings.mjs).
// tests/e2e/npm_pack.test.mjs type-checks an example that uses every export and checks that
// these declarations cover every member of the generated ones; tests/node/schema.test.mjs
// checks the tables against real sessions.
import type {
  TextureOptimizationOptions, TextureOptimizationEvent, GraphcutTexturesOptions, GraphcutTexturesEvent,
  GraphcutMergeOptions, GraphcutMergeEvent, FlowComponent, FlowAnimationOptions, FlowAnimationEvent,
  DeformationRanges, TileableOptions, TileableEvent, TextureBrushOptions, BrushStroke, LayerDesignOptions,
  LayerDesignEvent, DetectFeaturesOptions, FeatureSynthesisOptions, FeatureSynthesisEvent,
  VideoTexturesOptions, VideoTexturesEvent, InpaintingOptions, InpaintingEvent,
} from './schema.js';
// Every option object and event interface, generated from the bindings' tables.
export type * from './schema.js';

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
  /**
   * Material sets: `other` (an image of the exemplar's size: a normal, height or roughness map)
   * re-indexed by the output's source map into `target` (output size, RGBA). Nothing is
   * averaged, so normals stay unit vectors.
   */
  /**
   * Adds an exemplar the matches may come from, before the first step; returns its index.
   * @throws {TexsynthError} after the first step, or an exemplar the options refuse.
   */
  addExemplar(exemplar: Exemplar): number;
  /** Which exemplar each output pixel comes from, each in its own colour (`addExemplar`'s index). */
  renderSourcesInto(target: RgbaTarget): void;
  /**
   * Guided synthesis: `sourceGuide` (the exemplar's size) and `targetGuide` (the output's size),
   * with the same channels, add `weight ||g_source - g_target||^2` to the search's distance.
   * Style transfer: the exemplar's luminance as the source guide, a photo's as the target's.
   * With several exemplars, set the guides first, then add each exemplar with its own source
   * guide (`addGuidedExemplar`).
   * @throws {TexsynthError} after the first step, sizes or channels that differ, a bad weight.
   */
  setGuides(sourceGuide: Exemplar, targetGuide: Exemplar, weight: number): void;
  /**
   * Adds an exemplar with its source guide (the exemplar's size, the guides' channels) to a
   * guided session, before the first step; returns its index. Each match compares the guide of
   * the exemplar it lies in with the target guide.
   * @throws {TexsynthError} without `setGuides` first, after the first step, a guide of the
   *   wrong size or channels.
   */
  addGuidedExemplar(exemplar: Exemplar, sourceGuide: Exemplar): number;
  transferInto(other: Exemplar, target: RgbaTarget): void;
  renderInto(target: RgbaTarget): void;
  /** The colour-coded offset map (red = exemplar x, green = exemplar y). */
  renderOffsetMapInto(target: RgbaTarget): void;
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


export interface Rect { x: number; y: number; width: number; height: number }


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
  /**
   * Material sets: `other` (an image of the exemplar's size: a normal, height or roughness map)
   * re-indexed by the output's source map into `target` (output size, RGBA). Nothing is
   * averaged, so normals stay unit vectors.
   */
  /**
   * Adds an exemplar the patches may come from, before the first step; returns its index.
   * @throws {TexsynthError} after the first step, or an exemplar the options refuse.
   */
  addExemplar(exemplar: Exemplar): number;
  /** Which exemplar each output pixel comes from, each in its own colour (`addExemplar`'s index). */
  renderSourcesInto(target: RgbaTarget): void;
  transferInto(other: Exemplar, target: RgbaTarget): void;
  renderInto(target: RgbaTarget): void;
  /** The label map: every patch in its own colour. */
  renderLabelsInto(target: RgbaTarget): void;
  /** The per-pixel seam cost as a heat map. */
  renderSeamCostInto(target: RgbaTarget): void;
  /** Seam pixels opaque red, the rest transparent. */
  renderSeamsInto(target: RgbaTarget): void;
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


/** Interactive merging of up to 8 sources (Kwatra et al. 2003, section 6). */
export class GraphcutMerge implements Steppable<GraphcutMergeEvent> {
  /** An empty `outputWidth` x `outputHeight` merge; add sources, then step. */
  constructor(options?: GraphcutMergeOptions);
  /** The estimated peak working set in bytes (of the sources added so far). */
  readonly memoryEstimate: number;
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
  renderSeamsInto(target: RgbaTarget): void;
  renderSourcesInto(target: RgbaTarget): void;
  /** How many output pixels each source shows so far, by `addSource`'s index. */
  sourcePixels(): Uint32Array;
  /** Records each step's seam graph for `placementGraph()` (off by default). */
  setAnatomy(on: boolean): void;
  /** The last step's seam graph, painted pixels as its constraint nodes (kind 3: held to the
   * composite so far; 4: to the new source); null unless `setAnatomy(true)` came first. */
  placementGraph(): PlacementGraph | null;
  readonly done: boolean;
  readonly width: number;
  readonly height: number;
}

// ---------------------------------------------------------------- inpainting and uncrop

/**
 * Fills a hole in an image (Kwatra et al. 2003's graph cut from the outside in, then Kwatra et
 * al. 2005's texture optimisation with the known pixels as hard constraints); pixels outside
 * the hole are never changed. Uncrop: `extendBorder`, then this session.
 */
export class Inpainting implements Steppable<InpaintingEvent> {
  /**
   * Fills the pixels of `image` where `mask` (one byte per pixel) is non-zero, from the rest of
   * the image.
   * @throws {TexsynthError} a mask of the wrong size, an empty or a full mask, unknown option
   * keys, impossible values.
   */
  constructor(image: Exemplar, mask: Bytes, options?: InpaintingOptions);
  /** Like the constructor, filling from `exemplar` instead of the image's known part. */
  static withExemplar(image: Exemplar, mask: Bytes, exemplar: Exemplar, options?: InpaintingOptions): Inpainting;
  /** The part of the image worked on: the hole's bounds and a margin. */
  readonly region: Rect;
  /** The estimated peak working set in bytes (what the memory budget is checked against). */
  readonly memoryEstimate: number;
  free(): void;
  [Symbol.dispose](): void;
  [Symbol.iterator](): Iterator<InpaintingEvent>;
  run(options?: RunOptions<InpaintingEvent>): Promise<InpaintingEvent | null>;
  /** Places one patch of the fill, or runs one EM iteration (or part of one) of the optimisation. */
  step(): InpaintingEvent;
  /** The image: the known pixels exactly as given, the hole as filled so far. */
  renderInto(target: RgbaTarget): void;
  /** The fill's patches, each in its own colour; known pixels grey, unfilled ones transparent. */
  renderPatchesInto(target: RgbaTarget): void;
  readonly done: boolean;
  readonly width: number;
  readonly height: number;
}

/** A border's widths in pixels: one number for all four sides, or per side (missing sides: 0). */
export type Border = number | { top?: number; right?: number; bottom?: number; left?: number };
/**
 * Uncrop's input: `image` inside a border of `border` pixels, and the mask that marks the
 * border as the hole, for `new Inpainting(image, mask, options)`.
 */
export function extendBorder(image: Exemplar, border: Border): { image: Exemplar; mask: Uint8Array };

// ---------------------------------------------------------------- flow animation

export type FlowKind = 'sink' | 'source' | 'vortex' | 'shear' | 'translation';


/** A flow: a generator, a sum of generators, one field of (vx, vy) per pixel, or one per frame (cycled). */
export type Flow = FlowComponent | { components: FlowComponent[] } | Float32Array | Float32Array[];



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

/** The set of deformed textures, at most 64. */
export function deformationSet(exemplar: Exemplar, ranges: DeformationRanges): { label: string; exemplar: Exemplar }[];

export interface TileableResult {
  exemplar: Exemplar; cutX: number; cutY: number; seamCostX: number; seamCostY: number;
  /** RGBA, red on the stitches. */
  seam: Uint8ClampedArray;
}
/** Makes an image cyclic in one call. */
export function makeTileable(exemplar: Exemplar, options?: TileableOptions): TileableResult;

/** Making an image cyclic one graph cut per step. */
export class TileableTexture implements Steppable<TileableEvent> {
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

/** Local deformation with a brush; undoable. */
export class TextureBrush {
  constructor(base: Exemplar, options?: TextureBrushOptions);
  /** The estimated peak working set in bytes (what the memory budget is checked against). */
  readonly memoryEstimate: number;
  free(): void;
  [Symbol.dispose](): void;
  stroke(reference: Exemplar, mask: Bytes, dx: number, dy: number): BrushStroke;
  /** nu of eq. 2 for the strokes to come (finite, 0 to 1e9); the strokes made and the undo history stay. */
  setNu(nu: number): void;
  undo(): boolean;
  renderInto(target: RgbaTarget): void;
  renderLabelsInto(target: RgbaTarget): void;
  toExemplar(): Exemplar;
  readonly undoDepth: number;
  readonly width: number;
  readonly height: number;
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
  renderFeaturesInto(target: RgbaTarget): void;
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
  renderFrameInto(t: number, target: RgbaTarget): void;
  /** Seam overlay of frame t: spatial seams opaque red, temporal seams translucent yellow, transparent elsewhere. */
  renderSeamsInto(t: number, target: RgbaTarget): void;
  /** The x-t slice at row y (`width` x `frames`, row t = frame t) with the seams in red (`width * frames * 4`). */
  renderSliceXtInto(y: number, target: RgbaTarget): void;
  /** Output frame t as a new RGBA array (for workers: `remote.call('frame', t)`). */
  frame(t: number): Uint8ClampedArray;
  /** The seam overlay of frame t as a new RGBA array. */
  seams(t: number): Uint8ClampedArray;
  /** The x-t slice at row y as a new RGBA array (`width` x `frames`). */
  sliceXt(y: number): Uint8ClampedArray;
  /** The frame the last patch reached into (frame 0 before the first step), as RGBA. */
  renderInto(target: RgbaTarget): void;
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

/** Whether this module was built with threads: true from `texsynth-wasm/threads`. */
export function threaded(): boolean;

/** Threads a synthesis runs on: the thread pool's size, 1 for the default module. */
export function threadCount(): number;
