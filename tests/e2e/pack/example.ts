// Uses every exported API with its types; `tsc --noEmit` on this file is the TypeScript test.
// Lines marked @ts-expect-error must fail to type-check: they prove the types are not `any`.
import init, {
  Exemplar, FlowAnimation, GraphcutMerge, GraphcutTextures, LayerDesign, TextureBrush, TextureOptimization,
  FeatureMap, FeatureSynthesis, detectFeatures, measureBrokenFeatures, VideoClip, VideoTextures,
  TileableTexture, deformTexture, deformationSet, flowField, initSync, makeTileable, measureQuality, start, version,
  yieldToEventLoop,
  type FlowAnimationEvent, type GraphcutTexturesEvent, type Quality, type TextureOptimizationEvent, type TexsynthError,
} from 'texsynth-wasm';
import { init as initWeb } from 'texsynth-wasm/web';
import { createPool, createWorker, type WorkerImage } from 'texsynth-wasm/worker';
import type * as Generated from 'texsynth-wasm/texsynth.js';

declare const bytes: Uint8Array;
declare const signal: AbortSignal;

async function everything(): Promise<void> {
  await init();
  await init(new URL('https://example.com/texsynth_bg.wasm'));
  await initWeb(await fetch('texsynth_bg.wasm'));
  initSync(bytes);
  await yieldToEventLoop();
  start();
  const v: string = version();

  const ex = Exemplar.fromBytes(bytes);
  const ex2 = Exemplar.fromRgba(ex.toRgba(), ex.width, ex.height);
  Exemplar.fromImageData({ data: ex.toRgba(), width: ex.width, height: ex.height });
  const png: Uint8Array = ex.toPng();
  const working: Exemplar = ex.resized(256).cropped(0, 0, 32, 32);
  const rgba = new Uint8ClampedArray(256 * 256 * 4);
  ex.renderInto(rgba);
  const channels: number = ex.channels;

  const to = new TextureOptimization(ex, { outputWidth: 256, seed: 7, search: 'kmeans-tree', energy: 'haar', neighbourhoodSizes: [16, 8], memoryBudgetMiB: 512 });
  const estimate: number = to.memoryEstimate;
  for (const event of to) {
    const e: number = event.energy;
    const k: 'level' | 'iteration' | 'part' | 'done' = event.kind;
    const p: number = event.progress;
  }
  const last: TextureOptimizationEvent | null = await to.run({ signal, onEvent: (event) => event.neighbourhoodSize });
  to.renderInto(rgba);
  to.renderOffsetMapInto(rgba);

  const map: FeatureMap = detectFeatures(ex, { features: 'ridges', threshold: 0.9 });
  map.paint(3, 4, 2, true);
  const fg = FeatureSynthesis.withFeatureMap(ex, map, { patchSize: 32, warp: true, extraInputs: ['mirror'] });
  for (const event of new FeatureSynthesis(ex, { outputWidth: 64 })) {
    const w: 'none' | 'spline' | 'shepard' | 'skipped' | 'unavailable' = event.warp;
  }
  const fe = fg.step();
  const pairs: Float32Array = fg.placement().pairs;
  fg.renderFeaturesInto(rgba);
  const broken: number = measureBrokenFeatures(ex, rgba, 256, 256, { features: 'edges' });
  // @ts-expect-error: not a feature kind
  detectFeatures(ex, { features: 'corners' });
  const clip = VideoClip.fromFrames(8, 8, 12, new Uint8Array(8 * 8 * 4 * 12));
  const video = new VideoTextures(clip, { mode: 'extend', outputWidth: 16, fixedFrames: 2, placement: 'sub-patch' });
  for (const event of video) {
    const loopFrame: number | null = event.loopFrame;
    const offsetT: number | undefined = event.patch?.offsetT;
  }
  video.renderFrameInto(0, new Uint8ClampedArray(video.width * video.height * 4));
  video.renderSliceXtInto(0, new Uint8ClampedArray(video.width * video.frames * 4));
  const frame: Uint8ClampedArray = video.frame(0);
  const slice: Uint8ClampedArray = video.sliceXt(0);
  video.seams(0);
  video.renderInto(new Uint8ClampedArray(video.width * video.height * 4));
  // @ts-expect-error: not a video mode
  new VideoTextures(clip, { mode: 'bounce' });
  const history: Float64Array = to.energyHistory();
  const levels: Uint32Array = to.historyLevels();
  const plan = to.schedule().map((l) => l.neighbourhoodSize * l.scale);
  const field = to.field();
  if (field) field.matches.length;
  to.setConstraints(rgba, 2);
  to.clearConstraints();
  const ce: number = to.constraintEnergy + to.width + to.height;
  const search: 'patchmatch' | 'kmeans-tree' | 'exact' = to.search;
  const energyKind: string = to.energy;
  to.free();

  const gc = new GraphcutTextures(ex, { placement: 'sub-patch', blend: 'feather', scales: [0.5], rotate: true, tileable: true });
  const ge: GraphcutTexturesEvent = gc.step();
  const covered: boolean = ge.covered;
  if (ge.rect) ge.rect.width;
  gc.renderSeamsInto(rgba); gc.renderSeamCostInto(rgba); gc.renderLabelsInto(rgba); gc.renderInto(rgba);
  const region = gc.errorRegion();
  const names: string[] = gc.sources();
  for (const event of gc) event.patchesPlaced;

  const merge = new GraphcutMerge({ outputWidth: 200, outputHeight: 128 });
  merge.addSource(ex, 0, 0);
  merge.setConstraints(new Uint8Array(200 * 128));
  for (const event of merge) { const s: number | null = event.source; }
  merge.renderInto(rgba); merge.renderSeamsInto(rgba); merge.renderSourcesInto(rgba);

  const anim = new FlowAnimation(ex, { frames: 4, flow: { components: [{ type: 'vortex', strength: 2 }, { type: 'sink' }] } });
  await anim.run({ onEvent: (event: FlowAnimationEvent) => event.frameFinished && anim.renderInto(rgba) });
  anim.renderNaiveInto(rgba);
  const f: Float32Array = anim.flowField(0);
  anim.textureEnergyHistory(); anim.flowEnergyHistory();
  const frames: number = anim.frames + anim.framesFinished;
  flowField({ type: 'shear', strength: 1 }, 128, 128, 0);

  const deformed: Exemplar = deformTexture(ex, [{ rotate: 30 }, { scale: 0.75 }, { mirror: true }, { shift: [3, 4] }]);
  const set = deformationSet(ex, { rotation: { from: 0, to: 90, step: 30 }, mirror: true });
  const label: string = set[0].label;
  const tiled = makeTileable(ex, { overlapX: 8 });
  const cut: number = tiled.cutX + tiled.seamCostY;
  const ts = new TileableTexture(ex, { overlapY: 8 });
  for (const event of ts) { const axis: 'x' | 'y' = event.axis; }
  ts.renderInto(rgba);
  ts.result().exemplar.width;

  const brush = new TextureBrush(ex, { nu: 1000, poisson: false });
  const stroke = brush.stroke(ex2, new Uint8Array(ex2.width * ex2.height), 3, 4);
  stroke.pixelsTaken;
  brush.renderLabelsInto(rgba); brush.renderInto(rgba);
  const undone: boolean = brush.undo();
  brush.toExemplar().free();
  brush.undoDepth;

  const design = new LayerDesign({ outputWidth: 128, patchSize: 32, search: 'qtp', placement: 'best' });
  design.addLayer(ex, [{ flip: true }]);
  design.setLayout(new Uint8Array(128 * 128));
  await design.run();
  design.renderInto(rgba);
  design.toExemplar();

  const q: Quality = measureQuality(ex, rgba, 256, 256);
  q.flat;

  try { Exemplar.fromBytes(new Uint8Array(0)); } catch (error) { const e = error as TexsynthError; e.message; }

  const worker = createWorker();
  const remote = await worker.createSession('TextureOptimization', { bytes }, { outputWidth: 1024, outputHeight: 1024 });
  const stepped = await remote.step();
  const energy: number = stepped.event.energy;
  await remote.run({ signal, every: 2, onEvent: (event, image: WorkerImage | null) => { event.iteration; image?.data; } });
  const view: WorkerImage = await remote.render('renderOffsetMapInto');
  await remote.call('schedule');
  await remote.free();
  worker.terminate();
  const pool = createPool(2);
  const job = await pool.run('GraphcutTextures', [ex, { placement: 'random' }]);
  job.event?.totalSeamCost;
  pool.close();

  // @ts-expect-error unknown option key
  new TextureOptimization(ex, { outputWidht: 256 });
  // @ts-expect-error wrong option type
  new GraphcutTextures(ex, { placement: 'everywhere' });
  // @ts-expect-error events are typed
  const wrong: string = to.step().energy;
  // @ts-expect-error worker session kinds are checked
  await worker.createSession('TextureOptimisation', { bytes });
}

// The hand-written declarations cover every member of the generated ones: each typed class must
// be assignable to the generated class (a member missing here fails).
type Covers<Generated, Typed extends Generated> = Typed;
type _Coverage = [
  Covers<Generated.Exemplar, Exemplar>, Covers<Generated.TextureOptimization, TextureOptimization>,
  Covers<Generated.GraphcutTextures, GraphcutTextures>, Covers<Generated.GraphcutMerge, GraphcutMerge>,
  Covers<Generated.FlowAnimation, FlowAnimation>, Covers<Generated.TileableTexture, TileableTexture>,
  Covers<Generated.TextureBrush, TextureBrush>, Covers<Generated.LayerDesign, LayerDesign>,
  Covers<Generated.FeatureSynthesis, FeatureSynthesis>, Covers<Generated.FeatureMap, FeatureMap>,
  Covers<Generated.VideoClip, VideoClip>, Covers<Generated.VideoTextures, VideoTextures>,
];
// Every export of the generated module is declared (generated names are a subset of the typed).
type _Functions = Covers<keyof typeof import('texsynth-wasm'), keyof typeof import('texsynth-wasm/texsynth.js')>;
export { everything };
