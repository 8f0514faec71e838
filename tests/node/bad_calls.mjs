// Bad arguments to the positional parameters of every function and method JavaScript can call
// (the options objects are covered from the table of sessions.mjs): image files that are empty,
// truncated or lying about their size, 1x1 and huge sizes, NaN and strings where numbers belong,
// buffers of the wrong length or type. Each row: [what, call, expectation] (see corpus.mjs).
import { api, sampleBytes, tinyClip, tinyExemplar } from './fixtures.mjs';
import { exercise } from './sessions.mjs';

const png = sampleBytes('brick_64');
/** The PNG with its IHDR width and height replaced (a header that lies about the size). */
const lyingPng = (w, h) => {
  const bytes = png.slice();
  const view = new DataView(bytes.buffer);
  view.setUint32(16, w);
  view.setUint32(20, h);
  return bytes;
};
const ex = (side = 32) => tinyExemplar(side);
const rgba = (w, h) => new Uint8ClampedArray(w * h * 4).fill(200);
const OK = 'ok';

/** Options whose `key` has a getter that throws: the library must name the option (the corpus's
 * option rows cannot carry a getter: their sessions spread the options into defaults). */
const throwing = (key) => ({ get [key]() { throw new Error('getter failed'); } });

export const BAD_CALLS = [
  ['TextureOptimization: a throwing getter', () => new api.TextureOptimization(ex(), throwing('outputWidth')), 'outputWidth'],
  ['FlowAnimation: a throwing getter', () => new api.FlowAnimation(ex(), throwing('lambda')), 'lambda'],
  ['GraphcutTextures: a throwing getter', () => new api.GraphcutTextures(ex(), throwing('seed')), 'seed'],
  ['FeatureSynthesis: a throwing getter', () => new api.FeatureSynthesis(ex(), throwing('patchSize')), 'patchSize'],
  ['TextureOptimization: a Proxy whose ownKeys throws', () => new api.TextureOptimization(ex(), new Proxy({}, { ownKeys() { throw new Error('trap failed'); } })), 'options'],
  // Image files.
  ['fromBytes: empty', () => api.Exemplar.fromBytes(new Uint8Array(0)), 'empty input'],
  ['fromBytes: one byte', () => api.Exemplar.fromBytes(new Uint8Array([0x89])), 'could not decode'],
  ['fromBytes: truncated PNG', () => api.Exemplar.fromBytes(png.slice(0, png.length >> 1)), 'could not decode'],
  ['fromBytes: PNG header only', () => api.Exemplar.fromBytes(png.slice(0, 33)), 'could not decode'],
  ['fromBytes: JPEG magic, no body', () => api.Exemplar.fromBytes(new Uint8Array([0xff, 0xd8, 0xff, 0xe0, 0, 16])), 'could not decode'],
  ['fromBytes: text', () => api.Exemplar.fromBytes(new TextEncoder().encode('<html>not an image</html>')), 'could not decode'],
  ['fromBytes: PNG claiming 100000x100000', () => api.Exemplar.fromBytes(lyingPng(100000, 100000)), /100000|could not decode/],
  ['fromBytes: PNG claiming 2^31 x 1', () => api.Exemplar.fromBytes(lyingPng(2 ** 31, 1)), /could not decode|size/],
  ['fromBytes: PNG claiming 0x0', () => api.Exemplar.fromBytes(lyingPng(0, 0)), /could not decode|size/],
  ['fromBytes: PNG claiming 1x1', () => api.Exemplar.fromBytes(lyingPng(1, 1)), /could not decode/],
  ['fromBytes: a string', () => api.Exemplar.fromBytes('not bytes'), /could not decode|empty|bytes/],
  ['fromBytes: null', () => api.Exemplar.fromBytes(null), /./],
  ['fromRgba: 0x0', () => api.Exemplar.fromRgba(new Uint8Array(0), 0, 0), '0x0'],
  ['fromRgba: 1x1', () => api.Exemplar.fromRgba(new Uint8Array(4), 1, 1), OK],
  ['fromRgba: short buffer', () => api.Exemplar.fromRgba(new Uint8Array(15), 2, 2), 'expected 16'],
  ['fromRgba: 65536x65536 claimed', () => api.Exemplar.fromRgba(new Uint8Array(16), 65536, 65536), '65536x65536'],
  ['fromRgba: NaN width', () => api.Exemplar.fromRgba(new Uint8Array(16), NaN, 2), 'size'],
  ['fromRgba: -1 width', () => api.Exemplar.fromRgba(new Uint8Array(16), -1, 2), 'size'],
  ['fromRgba: string width', () => api.Exemplar.fromRgba(new Uint8Array(16), 'two', 2), 'size'],
  ['fromImageData: number', () => api.Exemplar.fromImageData(3), 'imageData'],
  ['fromImageData: no data', () => api.Exemplar.fromImageData({ width: 2, height: 2 }), 'imageData.data'],
  ['fromImageData: lying height', () => api.Exemplar.fromImageData({ width: 2, height: 3, data: new Uint8ClampedArray(16) }), 'expected 24'],
  ['fromImageData: NaN width', () => api.Exemplar.fromImageData({ width: NaN, height: 2, data: new Uint8ClampedArray(16) }), 'imageData.width'],
  ['fromImageData: plain array data', () => api.Exemplar.fromImageData({ width: 1, height: 1, data: [1, 2, 3, 4] }), 'imageData.data'],
  // Exemplar methods.
  ['resized: 0', () => ex().resized(0), 'maxSide'],
  ['resized: NaN', () => ex().resized(NaN), 'maxSide'],
  ['resized: -5', () => ex().resized(-5), 'maxSide'],
  ['resized: 2.5', () => ex().resized(2.5), 'maxSide'],
  // Positional number parameters take JavaScript's number conversion ('16' is 16, 'x' is NaN).
  ['resized: numeric string', () => ex().resized('16'), OK],
  ['resized: string', () => ex().resized('sixteen'), 'maxSide'],
  ['resized: 1', () => ex().resized(1), OK],
  ['resized: 1e300', () => ex().resized(1e300), OK],
  ['cropped: outside', () => ex().cropped(30, 0, 8, 8), 'does not fit'],
  ['cropped: negative x', () => ex().cropped(-1, 0, 8, 8), 'x'],
  ['cropped: NaN width', () => ex().cropped(0, 0, NaN, 8), 'width'],
  ['cropped: zero height', () => ex().cropped(0, 0, 8, 0), 'crop'],
  ['cropped: huge', () => ex().cropped(0, 0, 1e9, 1e9), /crop|fit|size/],
  ['cropped: 1x1', () => ex().cropped(31, 31, 1, 1), OK],
  ['Exemplar.renderInto: short', () => ex().renderInto(new Uint8ClampedArray(10)), 'target pixel array'],
  ['Exemplar.renderInto: null', () => ex().renderInto(null), 'target'],
  ['Exemplar.renderInto: number', () => ex().renderInto(7), 'target'],
  // measureQuality.
  ['measureQuality: short pixels', () => api.measureQuality(ex(), rgba(4, 4), 5, 5), 'expected 100'],
  ['measureQuality: 0x0', () => api.measureQuality(ex(), new Uint8Array(0), 0, 0), '0x0'],
  ['measureQuality: 1x1', () => api.measureQuality(ex(), rgba(1, 1), 1, 1), /size|neighbourhood|small|./],
  ['measureQuality: NaN size', () => api.measureQuality(ex(), rgba(4, 4), NaN, NaN), /size/],
  ['measureQuality: 65536x65536 claimed', () => api.measureQuality(ex(), rgba(4, 4), 65536, 65536), /size/],
  ['measureQuality: 4096x4096 output, past the memory budget', () => api.measureQuality(ex(), new Uint8Array(4096 * 4096 * 4), 4096, 4096), /output 4096x4096: measuring quality needs about 1\.\d GiB .*patch index/],
  // A photo used whole as the exemplar: the exemplar is named, with what to do (no budget option).
  ['measureQuality: 4000x3000 exemplar, past the memory budget', () => api.measureQuality(api.Exemplar.fromRgba(new Uint8Array(4000 * 3000 * 4), 4000, 3000), rgba(64, 64), 64, 64), /^exemplar 4000x3000: measuring quality needs about 1\.\d GiB .*shrink or crop the exemplar first \(Exemplar\.resized, Exemplar\.cropped\)$/],
  ['measureQuality: 1x1 exemplar', () => api.measureQuality(api.Exemplar.fromRgba(new Uint8Array(4), 1, 1), rgba(8, 8), 8, 8), { either: /size|exemplar|small/ }],
  // flowField.
  ['flowField: not an object', () => api.flowField('vortex', 8, 8, 0), 'flow'],
  ['flowField: 0x0', () => api.flowField({ type: 'vortex' }, 0, 0, 0), 'size'],
  ['flowField: huge', () => api.flowField({ type: 'vortex' }, 1e9, 1e9, 0), 'size'],
  ['flowField: -1 width', () => api.flowField({ type: 'vortex' }, -1, 8, 0), 'size'],
  ['flowField: t = 2^32 - 1', () => api.flowField({ type: 'vortex', period: 7 }, 8, 8, 2 ** 32 - 1), OK],
  ['flowField: t = NaN', () => api.flowField({ type: 'vortex' }, 8, 8, NaN), OK],
  // GraphcutMerge.
  ['GraphcutMerge: 0x0', () => new api.GraphcutMerge({ outputWidth: 0, outputHeight: 0 }), 'outputWidth'],
  ['GraphcutMerge: huge', () => new api.GraphcutMerge({ outputWidth: 1e6, outputHeight: 1e6 }), 'outputWidth'],
  ['GraphcutMerge: step with no source', () => new api.GraphcutMerge({ outputWidth: 16, outputHeight: 16 }).step(), { either: /source/ }],
  ['GraphcutMerge: mask too short', () => new api.GraphcutMerge({ outputWidth: 16, outputHeight: 16 }).setConstraints(new Uint8Array(10)), 'constraint mask'],
  ['GraphcutMerge: mask names a missing source', () => {
    const merge = new api.GraphcutMerge({ outputWidth: 16, outputHeight: 16 });
    merge.addSource(ex(), 0, 0);
    merge.setConstraints(new Uint8Array(256).fill(9));
    return merge.step();
  }, { either: /source|constraint/ }],
  ['GraphcutMerge: source far outside', () => {
    const merge = new api.GraphcutMerge({ outputWidth: 16, outputHeight: 16 });
    merge.addSource(ex(), -(2 ** 31), 2 ** 31 - 1);
    merge.addSource(ex(), 1e10, NaN);
    for (let i = 0; i < 4 && !merge.done; i++) merge.step();
    return merge.renderInto(rgba(16, 16));
  }, { either: /source|position|outside/ }],
  ['GraphcutMerge: nine sources', () => {
    const merge = new api.GraphcutMerge({ outputWidth: 16, outputHeight: 16 });
    for (let i = 0; i < 9; i++) merge.addSource(ex(8), i, i);
  }, 'at most 8 sources'],
  ['GraphcutMerge: render into short', () => new api.GraphcutMerge({ outputWidth: 16, outputHeight: 16 }).renderInto(rgba(2, 2)), 'target pixel array'],
  // VideoClip / VideoTextures views.
  ['VideoClip: short frames', () => api.VideoClip.fromFrames(8, 8, 4, new Uint8Array(8 * 8 * 4 * 3)), /length|expected/],
  ['VideoClip: zero frames', () => api.VideoClip.fromFrames(8, 8, 0, new Uint8Array(0)), /frame|size/],
  ['VideoClip: 1x1x1', () => api.VideoClip.fromFrames(1, 1, 1, new Uint8Array(4)), { either: /size|frame|small/ }],
  ['VideoClip: huge claimed', () => api.VideoClip.fromFrames(65536, 65536, 65536, new Uint8Array(16)), /size|length|expected|budget/],
  ['VideoTextures: 1x1x1 clip', () => new api.VideoTextures(api.VideoClip.fromFrames(1, 1, 1, new Uint8Array(4)), {}), { either: /size|frame|small|clip/ }],
  // Found by the fuzz target `options`: the working-set estimate overflowed.
  ['VideoTextures: extend to 65536^3', () => new api.VideoTextures(tinyClip(), { mode: 'extend', fixedFrames: 0, outputWidth: 65536, outputHeight: 65536, outputFrames: 65536 }), 'output'],
  ['VideoTextures: extend to 65536x65536x2', () => new api.VideoTextures(tinyClip(), { mode: 'extend', fixedFrames: 0, outputWidth: 65536, outputHeight: 65536, outputFrames: 2 }), 'output'],
  ['VideoTextures: renderFrameInto past the end', () => new api.VideoTextures(tinyClip(), {}).renderFrameInto(1000, new Uint8Array(12 * 12 * 4)), /frame/],
  ['VideoTextures: renderFrameInto short', () => new api.VideoTextures(tinyClip(), {}).renderFrameInto(0, new Uint8Array(3)), /length|expected/],
  ['VideoTextures: sliceXt past the bottom', () => new api.VideoTextures(tinyClip(), {}).sliceXt(1000), /row|y/],
  ['VideoTextures: seams past the end', () => new api.VideoTextures(tinyClip(), {}).seams(2 ** 32 - 1), /frame/],
  // Texture design.
  ['deformTexture: rotate NaN', () => api.deformTexture(ex(), { rotate: NaN }), 'rotate'],
  ['deformTexture: scale 0', () => api.deformTexture(ex(), { scale: 0 }), 'scale'],
  ['deformTexture: scale -1', () => api.deformTexture(ex(), { scale: -1 }), 'scale'],
  ['deformTexture: scale 1e9', () => api.deformTexture(ex(), { scale: 1e9 }), /scale|size/],
  ['deformTexture: scale 1e-9', () => api.deformTexture(ex(), { scale: 1e-9 }), /scale|size/],
  ['deformTexture: shift of one', () => api.deformTexture(ex(), { shift: [1] }), 'shift'],
  ['deformTexture: shift 1e300', () => api.deformTexture(ex(), { shift: [1e300, 0] }), 'shift'],
  ['deformTexture: two in one', () => api.deformTexture(ex(), { rotate: 30, scale: 2 }), 'deformation'],
  ['deformTexture: seventeen', () => api.deformTexture(ex(), new Array(17).fill({ mirror: true })), 'deformations'],
  ['deformTexture: unknown', () => api.deformTexture(ex(), { twist: 3 }), "unknown option 'twist'"],
  ['deformTexture: a string', () => api.deformTexture(ex(), 'rotate'), /deformation|options/],
  ['deformTexture: 1x1 rotated 45', () => api.deformTexture(api.Exemplar.fromRgba(new Uint8Array(4), 1, 1), { rotate: 45 }), { either: /size|rotate|small/ }],
  ['TextureBrush.stroke: short mask', () => new api.TextureBrush(ex(), {}).stroke(ex(), new Uint8Array(5), 0, 0), 'mask'],
  ['TextureBrush.stroke: empty mask', () => new api.TextureBrush(ex(), {}).stroke(ex(), new Uint8Array(32 * 32), 0, 0), { either: /mask|paint/ }],
  ['TextureBrush.stroke: far offset', () => {
    const mask = new Uint8Array(32 * 32).fill(1);
    return new api.TextureBrush(ex(), {}).stroke(ex(), mask, 2 ** 31 - 1, -(2 ** 31));
  }, { either: /outside|offset|base|dx|window/ }],
  ['TextureBrush.stroke: NaN offset', () => new api.TextureBrush(ex(), {}).stroke(ex(), new Uint8Array(32 * 32).fill(1), NaN, NaN), { either: /mask/ }],
  ['TextureBrush.undo with nothing', () => new api.TextureBrush(ex(), {}).undo(), OK],
  ['LayerDesign: step with no layer', () => new api.LayerDesign({ outputWidth: 16, outputHeight: 16, patchSize: 8 }).step(), 'layers'],
  ['LayerDesign: layer smaller than a patch', () => new api.LayerDesign({ patchSize: 64 }).addLayer(ex(), undefined), 'patch size'],
  ['LayerDesign: layout too short', () => new api.LayerDesign({ outputWidth: 16, outputHeight: 16, patchSize: 8 }).setLayout(new Uint8Array(3)), 'layout'],
  ['LayerDesign: layout names a missing layer', () => {
    const d = new api.LayerDesign({ outputWidth: 16, outputHeight: 16, patchSize: 8 });
    d.addLayer(ex(), undefined);
    d.setLayout(new Uint8Array(256).fill(200));
    return d.step();
  }, { either: /layout|layer/ }],
  ['LayerDesign: seventeen layers', () => {
    const d = new api.LayerDesign({ outputWidth: 16, outputHeight: 16, patchSize: 8 });
    for (let i = 0; i < 17; i++) d.addLayer(ex(8), undefined);
  }, 'at most 16 layers'],
  ['LayerDesign: toExemplar before a step', () => new api.LayerDesign({ outputWidth: 16, outputHeight: 16, patchSize: 8 }).toExemplar(), 'has not stepped'],
  ['TileableTexture: result before done', () => new api.TileableTexture(ex(), {}).result(), 'not done'],
  ['makeTileable: overlap larger than the image', () => api.makeTileable(ex(), { overlapX: 40 }), /overlap/],
  ['makeTileable: 1x1', () => api.makeTileable(api.Exemplar.fromRgba(new Uint8Array(4), 1, 1), {}), { either: /size|overlap|small/ }],
  // Feature-guided synthesis.
  ['FeatureMap.paint: NaN', () => api.detectFeatures(ex(), {}).paint(NaN, 0, 2, true), 'x'],
  ['FeatureMap.paint: radius 1e9', () => api.detectFeatures(ex(), {}).paint(0, 0, 1e9, true), 'radius'],
  ['FeatureMap.paint: far outside', () => api.detectFeatures(ex(), {}).paint(-1e30, 1e30, 3, true), OK],
  ['FeatureMap.paintLine: NaN end', () => new api.FeatureMap(ex(), {}).paintLine(0, 0, 5, NaN, 1, true), 'y1'],
  ['FeatureMap.paintLine: radius 65', () => new api.FeatureMap(ex(), {}).paintLine(0, 0, 5, 5, 65, true), 'radius'],
  ['FeatureMap.paintLine: an end 1e30 away', () => new api.FeatureMap(ex(), {}).paintLine(-1e30, 3, 1e30, 3, 1, true), 'x0'],
  ['FeatureMap.paintLine: far off the map', () => new api.FeatureMap(ex(), {}).paintLine(-1e8, -1e8, -1e7, 1e8, 1, false), OK],
  ['FeatureMap.brokenFeatures: short pixels', () => new api.FeatureMap(ex(), {}).brokenFeatures(rgba(2, 2), 3, 3), 'expected 36'],
  ['FeatureMap.brokenFeatures: 1x1', () => new api.FeatureMap(ex(), {}).brokenFeatures(rgba(1, 1), 1, 1), { either: /size|small/ }],
  ['FeatureMap.scaledView: width 0', () => new api.FeatureMap(ex(), {}).scaledView(0, 8), 'width'],
  ['FeatureMap.scaledView: height 1e6', () => new api.FeatureMap(ex(), {}).scaledView(8, 1e6), 'height'],
  ['GraphcutTextures.carriedBrokenFeatures: short mask', () => new api.GraphcutTextures(ex(), { outputWidth: 16, outputHeight: 16 }).carriedBrokenFeatures(new Uint8Array(5)), 'featureMask'],
  ['GraphcutTextures.carriedBrokenFeatures: deformed sources', () => new api.GraphcutTextures(ex(), { outputWidth: 16, outputHeight: 16, rotate: true }).carriedBrokenFeatures(new Uint8Array(32 * 32)), 'sources'],
  ['GraphcutTextures.carriedBrokenFeatures: before any step', () => new api.GraphcutTextures(ex(), { outputWidth: 16, outputHeight: 16 }).carriedBrokenFeatures(new Uint8Array(32 * 32)), OK],
  ['GraphcutTextures.carriedBrokenFeaturesOf: the map of another exemplar size', () => new api.GraphcutTextures(ex(), { outputWidth: 16, outputHeight: 16 }).carriedBrokenFeaturesOf(api.detectFeatures(ex(16), {})), 'map'],
  ['GraphcutTextures.carriedBrokenFeaturesOf: not a map', () => new api.GraphcutTextures(ex(), { outputWidth: 16, outputHeight: 16 }).carriedBrokenFeaturesOf(new Uint8Array(32 * 32)), 'FeatureMap'],
  ['GraphcutTextures.carriedBrokenFeaturesOf: deformed sources', () => new api.GraphcutTextures(ex(), { outputWidth: 16, outputHeight: 16, mirror: true }).carriedBrokenFeaturesOf(api.detectFeatures(ex(), {})), 'sources'],
  ['GraphcutTextures.carriedBrokenFeaturesOf: before any step', () => new api.GraphcutTextures(ex(), { outputWidth: 16, outputHeight: 16 }).carriedBrokenFeaturesOf(api.detectFeatures(ex(), {})), OK],
  ['FeatureSynthesis.carriedBrokenFeatures: before any step', () => new api.FeatureSynthesis(ex(), { outputWidth: 32, outputHeight: 32, patchSize: 16 }).carriedBrokenFeatures(), OK],
  ['new FeatureMap: bad threshold', () => new api.FeatureMap(ex(), { threshold: NaN }), 'threshold'],
  ['FeatureMap.renderInto: short', () => api.detectFeatures(ex(), {}).renderInto(new Uint8ClampedArray(3)), 'target pixel array'],
  ['FeatureSynthesis.withFeatureMap: map of another size', () => {
    const map = api.detectFeatures(ex(16), {});
    return api.FeatureSynthesis.withFeatureMap(ex(), map, { outputWidth: 32, outputHeight: 32, patchSize: 16 }).step();
  }, /feature map|size/],
  ['FeatureSynthesis.withFeatureMap: an Exemplar as map', () => api.FeatureSynthesis.withFeatureMap(ex(), ex(), {}), /FeatureMap/],
  ['FeatureSynthesis: patch larger than the exemplar', () => new api.FeatureSynthesis(ex(), { patchSize: 64, outputWidth: 64, outputHeight: 64 }), 'patchSize: 64 is larger than the 32x32 exemplar'],
  // Without a patchSize the default patch (64) is fitted to a smaller exemplar, as graph cut takes one.
  ['FeatureSynthesis: an exemplar under the default patch, no patchSize', () => exercise(new api.FeatureSynthesis(ex(), { outputWidth: 48, outputHeight: 48 })), OK],
  ['FeatureSynthesis: an exemplar under the smallest patch', () => new api.FeatureSynthesis(ex(15), {}), 'exemplar size 15x15: feature-guided synthesis needs at least 16x16'],
  // Found by the fuzz target `session_steps` (a panic natively): graph-cut placement fills an
  // output narrower than one patch.
  ['FeatureSynthesis: output narrower than a patch', () => exercise(new api.FeatureSynthesis(ex(), { outputWidth: 8, outputHeight: 40, patchSize: 16 })), OK],
  ['FeatureSynthesis: overlap larger than the patch', () => new api.FeatureSynthesis(ex(), { patchSize: 16, overlap: 16 }), 'overlap'],
  ['measureBrokenFeatures: short pixels', () => api.measureBrokenFeatures(ex(), rgba(2, 2), 3, 3, {}), 'expected 36'],
  ['measureBrokenFeatures: 1x1', () => api.measureBrokenFeatures(ex(), rgba(1, 1), 1, 1, {}), { either: /size|small/ }],
  // Soft constraints of texture optimization.
  ['setConstraints: wrong length', () => new api.TextureOptimization(ex(), { outputWidth: 16, outputHeight: 16 }).setConstraints(new Uint8Array(7), 1), 'constraint pixels'],
  ['setConstraints: NaN lambda', () => new api.TextureOptimization(ex(), { outputWidth: 16, outputHeight: 16 }).setConstraints(new Uint8Array(16 * 16 * 4), NaN), 'lambda'],
  ['setConstraints: lambda -1', () => new api.TextureOptimization(ex(), { outputWidth: 16, outputHeight: 16 }).setConstraints(new Uint8Array(16 * 16 * 4), -1), 'lambda'],
  ['setConstraints: lambda 1e300', () => new api.TextureOptimization(ex(), { outputWidth: 16, outputHeight: 16 }).setConstraints(new Uint8Array(16 * 16 * 4), 1e300), 'lambda'],
  ['setConstraints: lambda as a string', () => new api.TextureOptimization(ex(), { outputWidth: 16, outputHeight: 16 }).setConstraints(new Uint8Array(16 * 16 * 4), '1'), { either: 'lambda' }],
  ['renderOffsetMapInto: short', () => new api.TextureOptimization(ex(), { outputWidth: 16, outputHeight: 16 }).renderOffsetMapInto(new Uint8ClampedArray(4)), /target pixel array|step/],
  ['FlowAnimation.flowField: t huge', () => new api.FlowAnimation(ex(), { outputWidth: 8, outputHeight: 8, frames: 2, frameSizes: [4] }).flowField(2 ** 32 - 1), { either: 'flow' }],
  ['FlowAnimation.renderNaiveInto: short', () => new api.FlowAnimation(ex(), { outputWidth: 8, outputHeight: 8, frames: 2, frameSizes: [4] }).renderNaiveInto(new Uint8ClampedArray(1)), 'target pixel array'],
  // Step anatomy of flow animation and placement anatomy of video.
  ['FlowAnimation.renderWarpedInto: in frame 1', () => new api.FlowAnimation(ex(), { outputWidth: 8, outputHeight: 8, frames: 2, frameSizes: [4] }).renderWarpedInto(new Uint8ClampedArray(8 * 8 * 4)), 'renderWarpedInto'],
  ['FlowAnimation.renderWarpedInto: short, in frame 2', () => {
    const flow = new api.FlowAnimation(ex(), { outputWidth: 8, outputHeight: 8, frames: 3, frameSizes: [4], frameIterations: 1 });
    while (flow.framesFinished < 1) flow.step();
    flow.step();
    flow.renderWarpedInto(new Uint8ClampedArray(3));
  }, 'target pixel array'],
  ['FlowAnimation.renderWarpedInto: null', () => new api.FlowAnimation(ex(), { outputWidth: 8, outputHeight: 8, frames: 2, frameSizes: [4] }).renderWarpedInto(null), /target|renderWarpedInto/],
  ['FlowAnimation.field: before any step is null', () => {
    const field = new api.FlowAnimation(ex(), { outputWidth: 8, outputHeight: 8, frames: 2, frameSizes: [4] }).field();
    if (field !== null) throw new Error(`field() before a step returned ${field}`);
  }, OK],
  ['FlowAnimation.field: on a freed session', () => {
    const flow = new api.FlowAnimation(ex(), { outputWidth: 8, outputHeight: 8, frames: 2, frameSizes: [4] });
    flow.free();
    flow.field();
  }, 'null pointer passed to rust'],
  ['VideoTextures.placementGraph: before setAnatomy is null', () => {
    const video = new api.VideoTextures(tinyClip(), { transitionWindow: 4 });
    video.step();
    if (video.placementGraph() !== null || video.placementCosts() !== null) throw new Error('recorded without setAnatomy');
  }, OK],
  ['VideoTextures.placementCosts: on a freed session', () => {
    const video = new api.VideoTextures(tinyClip(), {});
    video.free();
    video.placementCosts();
  }, 'null pointer passed to rust'],
  ['GraphcutMerge.placementGraph: before setAnatomy is null', () => {
    const merge = new api.GraphcutMerge({ outputWidth: 16, outputHeight: 8 });
    merge.addSource(ex(), 0, 0);
    merge.step();
    if (merge.placementGraph() !== null) throw new Error('recorded without setAnatomy');
  }, OK],
  ['GraphcutMerge.placementGraph: on a freed merge', () => {
    const merge = new api.GraphcutMerge({ outputWidth: 16, outputHeight: 8 });
    merge.free();
    merge.placementGraph();
  }, 'null pointer passed to rust'],
  // Objects of the wrong class where an Exemplar belongs.
  ['a FeatureMap as an Exemplar', () => new api.TextureOptimization(api.detectFeatures(ex(), {}), {}), /Exemplar/],
  ['a plain object as an Exemplar', () => new api.GraphcutTextures({ width: 8, height: 8 }, {}), /Exemplar/],
  ['undefined as an Exemplar', () => new api.FlowAnimation(undefined, {}), /Exemplar|undefined/],
  // Inpainting, material sets, several exemplars, guides.
  ['Inpainting: a mask of numbers', () => new api.Inpainting(ex(), [1, 2, 3], {}), 'mask'],
  ['Inpainting: a string as the mask', () => new api.Inpainting(ex(), 'hole', {}), /mask|Uint8Array|string/],
  ['Inpainting.withExemplar: a plain object as the exemplar', () => api.Inpainting.withExemplar(ex(), new Uint8Array(32 * 32).fill(1, 0, 40), { width: 8 }, {}), /Exemplar/],
  ['extendBorder: NaN', () => api.extendBorder(ex(), NaN), 'border'],
  ['extendBorder: a huge border', () => api.extendBorder(ex(), 1e6), /extended image|size/],
  ['extendBorder: an array', () => api.extendBorder(ex(), [1, 2, 3, 4]), /border/],
  ['extendBorder: null', () => api.extendBorder(ex(), null), 'border'],
  ['GraphcutTextures.transferInto: a plain object', () => new api.GraphcutTextures(ex(), { outputWidth: 16, outputHeight: 16 }).transferInto({}, rgba(16, 16)), /Exemplar/],
  ['GraphcutTextures.transferInto: before any step (nothing covered)', () => new api.GraphcutTextures(ex(), { outputWidth: 16, outputHeight: 16 }).transferInto(ex(), rgba(16, 16)), OK],
  ['TextureOptimization.transferInto: a short target', () => {
    const s = new api.TextureOptimization(ex(), { outputWidth: 16, outputHeight: 16, neighbourhoodSizes: [4], iterations: 1 });
    exercise(s, 50);
    s.transferInto(ex(), new Uint8ClampedArray(7));
  }, 'target'],
  ['GraphcutTextures.addExemplar: undefined', () => new api.GraphcutTextures(ex(), {}).addExemplar(undefined), /Exemplar|undefined/],
  ['TextureOptimization.addExemplar: a 12x12 exemplar', () => new api.TextureOptimization(ex(), {}).addExemplar(ex(12)), /exemplar size 12x12/],
  ['TextureOptimization.setGuides: strings', () => new api.TextureOptimization(ex(), {}).setGuides('a', 'b', 1), /Exemplar/],
  ['TextureOptimization.setGuides: a weight of Infinity', () => new api.TextureOptimization(ex(), { outputWidth: 32, outputHeight: 32 }).setGuides(ex(), ex(), Infinity), 'guideWeight'],
];
