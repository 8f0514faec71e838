// `texsynth-wasm/worker`: sessions in a Web Worker (browsers) or a worker_threads Worker (Node).
import type {
  Exemplar, FlowAnimationEvent, FlowAnimationOptions, GraphcutMergeEvent, GraphcutMergeOptions, GraphcutTexturesEvent,
  GraphcutTexturesOptions, LayerDesignEvent, LayerDesignOptions, TextureBrushOptions,
  TextureOptimizationEvent, TextureOptimizationOptions, TileableEvent, TileableOptions,
  FeatureSynthesisEvent, FeatureSynthesisOptions, VideoTexturesEvent, VideoTexturesOptions,
  DetectFeaturesOptions, InpaintingEvent, InpaintingOptions,
} from './index.js';

/** A video clip to send to a worker: the frames' RGBA one after the other; it becomes a VideoClip. */
export interface ClipInput { clip: { width: number; height: number; frames: number; rgba: Uint8Array | Uint8ClampedArray } }

/** An exemplar to send to a worker: an Exemplar (copied), PNG/JPEG bytes, or raw RGBA. */
export type ExemplarInput = Exemplar | { bytes: ArrayBuffer | Uint8Array } | { rgba: Uint8Array | Uint8ClampedArray; width: number; height: number };

/** Session kinds with their constructor arguments and events. */
export interface SessionKinds {
  TextureOptimization: { args: [ExemplarInput, TextureOptimizationOptions?]; event: TextureOptimizationEvent };
  GraphcutTextures: { args: [ExemplarInput, GraphcutTexturesOptions?]; event: GraphcutTexturesEvent };
  FlowAnimation: { args: [ExemplarInput, FlowAnimationOptions?]; event: FlowAnimationEvent };
  TileableTexture: { args: [ExemplarInput, TileableOptions?]; event: TileableEvent };
  GraphcutMerge: { args: [GraphcutMergeOptions?]; event: GraphcutMergeEvent };
  LayerDesign: { args: [LayerDesignOptions?]; event: LayerDesignEvent };
  TextureBrush: { args: [ExemplarInput, TextureBrushOptions?]; event: never };
  FeatureSynthesis: { args: [ExemplarInput, FeatureSynthesisOptions?]; event: FeatureSynthesisEvent };
  /** Not a session: a feature map detected (and edited with `call('paintLine', ...)`) in the worker. */
  FeatureMap: { args: [ExemplarInput, DetectFeaturesOptions?]; event: never };
  /** A static constructor: the map argument is a FeatureMap made in the same worker (or its mirror). */
  'FeatureSynthesis.withFeatureMap': { args: [ExemplarInput, WorkerSession<'FeatureMap'>, FeatureSynthesisOptions?]; event: FeatureSynthesisEvent };
  VideoTextures: { args: [ClipInput, VideoTexturesOptions?]; event: VideoTexturesEvent };
  /** `mask`: one byte per image pixel, non-zero to fill. */
  Inpainting: { args: [ExemplarInput, Uint8Array, InpaintingOptions?]; event: InpaintingEvent };
  'Inpainting.withExemplar': { args: [ExemplarInput, Uint8Array, ExemplarInput, InpaintingOptions?]; event: InpaintingEvent };
}
export type SessionKind = keyof SessionKinds;

/** Pixels from the worker (transferred, yours to keep): usable as `new ImageData(data, width, height)`. */
export interface WorkerImage { data: Uint8ClampedArray; width: number; height: number }

/** A view method of the session that writes RGBA into a buffer. */
export type RenderMethod = 'renderInto' | 'renderOffsetMapInto' | 'renderSeamsInto' | 'renderSeamCostInto' | 'renderLabelsInto' | 'renderNaiveInto' | 'renderSourcesInto' | 'renderFeaturesInto' | 'renderPatchesInto';

export interface WorkerRunOptions<E> {
  /** Aborting pauses the session after the current step; `run` rejects with the signal's reason. */
  signal?: AbortSignal;
  /** Every event, with the image every `every` steps and at the end (null otherwise). */
  onEvent?: (event: E, image: WorkerImage | null) => void;
  /** Which view to stream. Default: 'renderInto'; null streams no image. */
  render?: RenderMethod | null;
  /** Send the image every this many steps. Default: 1. */
  every?: number;
}

export class WorkerSession<K extends SessionKind = SessionKind> {
  readonly kind: K;
  readonly width: number;
  readonly height: number;
  /** Whether the last event seen was the final one. */
  readonly done: boolean;
  step(options?: { render?: RenderMethod | null }): Promise<{ event: SessionKinds[K]['event']; image?: WorkerImage }>;
  /** Runs until done or paused: `{ paused, event }`. */
  run(options?: WorkerRunOptions<SessionKinds[K]['event']>): Promise<{ paused: boolean; event: SessionKinds[K]['event'] | null }>;
  /** Stops a run after the current step. */
  pause(): Promise<void>;
  /**
   * Calls a method or reads a getter of the session in the worker (schedule, field, energyHistory,
   * setConstraints, ...). Exemplar arguments as `{ exemplar }`; an Exemplar result comes back as
   * `{ width, height, png }` (`Exemplar.fromBytes(png)` rebuilds it).
   */
  call<T = unknown>(method: string, ...args: unknown[]): Promise<T>;
  /** A view rendered in the worker. */
  render(method?: RenderMethod, width?: number, height?: number): Promise<WorkerImage>;
  /**
   * measureQuality of the current output against the session's exemplar; with `maxSide`, a larger
   * output is scored on its central `maxSide` x `maxSide` window, which the result names.
   */
  quality(options?: { maxSide?: number }): Promise<import('./index.js').Quality & { window?: { x: number; y: number; width: number; height: number } }>;
  free(): Promise<void>;
}

/**
 * Which module a worker runs. 'auto': the threaded module on every core where it can run (a
 * cross-origin isolated page, or Node with the threaded build), the single-threaded one elsewhere.
 * A number: the threaded module with that many threads (1 to 64), or a failed `ready` naming why
 * it cannot run. false: the single-threaded module.
 */
export type WorkerThreads = 'auto' | false | number;

/** The module a worker runs: `reason` says why 'auto' fell back to the single-threaded one. */
export interface WorkerModuleInfo { threaded: boolean; threads: number; reason: string | null }

/** One worker; hosts any number of sessions. */
export class TexsynthWorker {
  readonly ready: Promise<WorkerModuleInfo>;
  /** What `ready` resolved to; null until then. */
  readonly info: WorkerModuleInfo | null;
  createSession<K extends SessionKind>(kind: K, ...args: SessionKinds[K]['args']): Promise<WorkerSession<K>>;
  terminate(): void;
}

/** Independent jobs over several workers. */
export class WorkerPool {
  run<K extends SessionKind>(
    kind: K,
    args: SessionKinds[K]['args'],
    options?: { signal?: AbortSignal; onEvent?: (event: SessionKinds[K]['event'], image: WorkerImage | null) => void; every?: number },
  ): Promise<{ event: SessionKinds[K]['event'] | null; image: WorkerImage | null }>;
  close(): void;
}

/** A worker; `threads` defaults to 'auto'. */
export function createWorker(options?: { threads?: WorkerThreads }): TexsynthWorker;
/** Default size: the core count, at most 4; each worker single-threaded unless `threads` says otherwise. */
export function createPool(size?: number, options?: { threads?: WorkerThreads }): WorkerPool;
