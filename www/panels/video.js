// The "Video textures" panel (Kwatra et al. 2003, section 7): graph-cut textures over an
// (x, y, t) volume. A clip comes in (the built-in demo clip, a video file decoded frame by frame,
// or an image sequence), each step places one spatio-temporal patch along a minimum-cut seam
// surface, and the page shows the frame the patch landed in with the seam drawn over it, an x-t
// slice through the volume where the seams show where in time the cut falls, and the loop point
// with the frames on either side of it. When the synthesis is done the output plays in a loop and
// can be recorded as WebM. The placement anatomy is the graph-cut panel's (graphcut-anatomy.js)
// for one slice of the 3-D placement: the costs over spatial offsets at the drawn time shift, and
// the seam graph in the frame of the patch with the most overlap (see src/methods/video/anatomy.rs).
import { clipFromImages, clipFromStrip, clipFromVideo, loadImage } from '../lib/video-input.js';
import { recordToLink } from '../lib/record.js';
import { explain } from '../lib/explain.js';
import { remoteSession } from '../lib/worker.js';
import { crossfadeLoop, fadeFrames } from '../lib/crossfade.js';
import { ANATOMY_HTML, showPlacementAnatomy } from './graphcut-anatomy.js';

export const id = 'video';
export const title = 'Video textures';

/** The built-in clips (scripts/make-demo-clip.mjs), by the value of their option. */
const DEMO_CLIPS = { water: './samples/clips/water.png', ripples: './samples/clips/ripples.png' };
const PLAYBACK_FPS = 15;

/** A loop's transition in the readout: the one seamed by this step, or the one kept at the end. */
function transitionText(event) {
  const tr = event.transition;
  if (!tr || tr.count < 2) return '';
  const which = `transition ${tr.index + 1} of ${tr.count} (loop of ${tr.loopLength} frames)`;
  return event.done ? ` · kept ${which}: its seam cost least` : ` · seaming ${which}`;
}

const FIXED_TITLE = 'frames held fixed at both ends of random offsets or a spatial extension so that it loops (7.D); 0: no loop';

const OPTIONS_HTML = `
  <label>Clip <select id="vt-source">
    <option value="water">demo: water (128×128, 60 frames)</option>
    <option value="ripples" title="three ripple sources, each with its own rhythm: a loop's seam cuts at different times across the frame">demo: ripples (128×128, 60 frames)</option>
    <option value="file">a video file or image sequence…</option>
  </select></label>
  <input id="vt-file" type="file" accept="video/*,image/*" multiple hidden>
  <label title="frames are scaled to this size before synthesis">size <input id="vt-size" type="number" value="64" min="16" max="256" step="8"></label>
  <label title="frames taken from the clip">frames <input id="vt-frames" type="number" value="40" min="4" max="240" step="1"></label>
  <label>Mode <select id="vt-mode">
    <option value="loop">loop (7.A)</option>
    <option value="offsets">random temporal offsets (7.B)</option>
    <option value="extend">spatial extension (7.E)</option>
  </select></label>
  <label>Placement <select id="vt-placement">
    <option value="random">random</option>
    <option value="entire-patch">entire-patch matching (eq. 2 in 3-D)</option>
    <option value="sub-patch">sub-patch matching (7.C)</option>
  </select></label>
  <label title="output frames (offsets and extension; a loop is as long as its transition); 0: the default">out frames <input id="vt-out-frames" type="number" value="0" min="0" max="480" step="1"></label>
  <label id="vt-fixed-label" title="${FIXED_TITLE}">k <input id="vt-fixed" type="number" value="10" min="0" max="60" step="1"></label>
  <label title="a spatial extension's frame size, as a multiple of the clip's (7.E)">extend × <select id="vt-scale">
    <option value="1.5">1.5</option>
    <option value="2" selected>2</option>
    <option value="3">3</option>
  </select></label>
  <label title="loop (7.A): the most frames of the seam window around the transition (the paper's 60; short clips get less)">window <input id="vt-window" type="number" value="60" min="3" max="240" step="1"></label>
  <label title="loop (7.A): how many good transitions get a seam surface (the best by frame difference, then the next best of other loop lengths around it); the cheapest seam is kept">transitions <input id="vt-transitions" type="number" value="3" min="1" max="16" step="1"></label>
  <label title="section 5: once done, each voxel near a seam becomes a Gaussian-weighted mix of the patches meeting there, across x, y and time">blend <select id="vt-blend">
    <option value="none">none</option>
    <option value="feather">feather</option>
  </select></label>
  <label title="patches placed over the worst seams once every voxel is covered (section 3.2)">refine <input id="vt-refine" type="number" value="2" min="0" max="50" step="1"></label>
  <label title="seam cost M′ (eq. 5): the colour difference divided by the gradients, so seams run along edges"><input id="vt-gradient" type="checkbox"> gradient cost M′</label>
  <label class="views" title="the row the x-t slice is taken at">slice row <input id="vt-row" class="view" type="range" min="0" max="63" value="32"></label>
  <label title="the cost surface (at the drawn time shift) and the seam graph (in one frame) of each placement"><input id="vt-anatomy-on" class="view" type="checkbox"> placement anatomy</label>
  <button id="vt-record" type="button" class="view">Record WebM</button>
  <a id="vt-download" hidden download="texsynth-video.webm">download video</a>`;

const SIDE_HTML = `
  <div class="readout" id="vt-readout">press Run or Step</div>
  <div class="explain" id="vt-explain" data-history-text aria-live="polite"></div>
  ${ANATOMY_HTML
    .replace('aria-label="Placement anatomy">', 'aria-label="Placement anatomy">\n    <p class="legend" id="vt-anatomy-slice"></p>')
    .replace('C(t), eq. 2', 'C(t), eq. 4, one time shift')
    .replace('section 3, 3.1</small>', 'sections 3, 3.1, 7; one frame</small>')}
  <div class="side-row">
    <figure><canvas id="vt-playback" width="128" height="128" style="width: 128px; image-rendering: pixelated" aria-label="Output, playing"></canvas>
      <figcaption id="vt-playback-caption">output, looping</figcaption></figure>
    <figure><canvas id="vt-input" width="128" height="128" style="width: 128px; image-rendering: pixelated" aria-label="Input clip, playing"></canvas>
      <figcaption id="vt-input-caption">input clip</figcaption></figure>
  </div>
  <div class="side-row">
    <figure><canvas id="vt-crossfade" width="128" height="128" style="width: 128px; image-rendering: pixelated" aria-label="Cross-fade loop of the clip, playing"></canvas>
      <figcaption id="vt-crossfade-caption">cross-fade loop (baseline)</figcaption></figure>
    <p class="legend">The baseline: the clip cut to the output's length, its first frames blended with
      the frames after the cut. Watch the ghosting it leaves where the graph-cut loop cuts instead.</p>
  </div>
  <figure><canvas id="vt-slice" class="slice" width="128" height="60" style="width: 100%; image-rendering: pixelated" aria-label="x-t slice with seams"></canvas>
    <figcaption id="vt-slice-caption">x-t slice (x across, time down), seams in red</figcaption></figure>
  <div class="side-row">
    <figure><canvas id="vt-loop-last" width="64" height="64" style="width: 128px; image-rendering: pixelated" aria-label="Frame before the loop point"></canvas>
      <figcaption>before the loop point</figcaption></figure>
    <figure><canvas id="vt-loop-first" width="64" height="64" style="width: 128px; image-rendering: pixelated" aria-label="Frame after the loop point"></canvas>
      <figcaption>after it</figcaption></figure>
  </div>
  <p class="legend" id="vt-loop-caption">The loop point and the frames on either side of it.</p>
`;

export function createPanel(ui) {
  let clip = null;
  let clipKey = null;
  let session = null;
  let pending = null;
  let output = [];
  let inputFrames = [];
  // The cross-fade loop of the clip, as long as the output (www/lib/crossfade.js).
  let baseline = [];
  let playTimer = null;
  let playIndex = 0;
  let recording = false;
  let shownFrame = 0;

  const anatomyOn = () => ui.$('vt-anatomy-on').checked;
  /** What the worker sends back with each step: the placement's anatomy while it is on. */
  const wanted = () => ({ getters: ['frames'], calls: anatomyOn() ? ['placementCosts', 'placementGraph'] : [] });

  /** The anatomy is recorded from the next placement on (the session keeps nothing otherwise). */
  async function toggleAnatomy() {
    ui.$('gc-anatomy').hidden = !anatomyOn();
    if (session) await session.send('setAnatomy', anatomyOn());
    if (anatomyOn()) {
      ui.$('gc-graph-readout').textContent = session ? 'recorded from the next placement on: press Step' : 'press Run or Step';
    }
  }

  /** Draws the last placement's slices; a placement without costs (random, the first patch,
   * a loop's copies, 7.D's fixed frames) leaves the cost maps blank and says why. */
  function drawAnatomy(event) {
    if (!anatomyOn()) return;
    const costs = session.result('placementCosts');
    const graph = session.result('placementGraph');
    showPlacementAnatomy(ui.$, costs, graph);
    if (!costs) {
      for (const id of ['gc-cost', 'gc-probability']) {
        const c = ui.$(id);
        c.getContext('2d').clearRect(0, 0, c.width, c.height);
      }
      delete ui.$('gc-cost-legend').dataset.offsets;
    }
    const where = costs
      ? (costs.axes === 'xy'
        ? `Costs over spatial offsets x ${costs.x}…${costs.x + costs.width - 1}, y ${costs.y}…${costs.y + costs.height - 1} at the drawn time shift t = ${costs.tt}`
        : `Costs over temporal offsets t ${costs.x}…${costs.x + costs.width - 1} (7.B: no spatial shift)`)
      : 'No cost surface: this patch was placed without matching (random placement, the first patch, a loop or 7.D’s fixed frames)';
    const frame = graph
      ? ` · graph: frame ${graph.frame + 1} of the patch’s frames ${graph.firstFrame + 1}–${graph.firstFrame + graph.frames}, the one with the most overlap`
      : '';
    ui.$('vt-anatomy-slice').textContent = `${where}${frame}.`;
    document.body.dataset.videoAnatomyPatches = String(event.patchesPlaced);
  }

  const size = () => Math.min(256, Math.max(16, Math.round(Number(ui.$('vt-size').value) || 64)));
  const frameCount = () => Math.min(240, Math.max(4, Math.round(Number(ui.$('vt-frames').value) || 40)));

  /** The clip at the chosen size, decoded once per source and size. A decode that another
   * request has superseded (the size changed while a video was decoding) is dropped. */
  let loading = null;
  let mounted = true;
  async function loadClip() {
    const files = ui.$('vt-file').files;
    const fromFile = ui.$('vt-source').value === 'file' && files.length > 0;
    const demo = DEMO_CLIPS[ui.$('vt-source').value] ?? DEMO_CLIPS.water;
    const key = `${fromFile ? [...files].map((f) => f.name).join('|') : demo}:${size()}:${frameCount()}`;
    if (clip && clipKey === key) return clip;
    if (loading?.key !== key) loading = { key, promise: decodeClip(fromFile ? files : null, key, demo) };
    const { promise } = loading;
    const loaded = await promise;
    if (loading?.key !== key) return loadClip();
    loading = null;
    clip = loaded;
    clipKey = key;
    inputFrames = framesOf(clip);
    // The decode may end after the panel was left: its elements are gone then.
    if (mounted) ui.$('vt-input-caption').textContent = `input clip: ${clip.width}×${clip.height}, ${clip.frames} frames`;
    return clip;
  }

  async function decodeClip(files, key, demo) {
    const s = size();
    let loaded;
    if (!files) {
      loaded = clipFromStrip(await loadImage(demo), { width: s, height: s });
    } else if (files.length === 1 && files[0].type.startsWith('video/')) {
      loaded = await clipFromVideo(files[0], {
        width: s, height: s, frames: frameCount(),
        onProgress: (t, n) => {
          if (mounted && loading?.key === key) ui.$('vt-readout').textContent = `decoding frame ${t}/${n}…`;
        },
      });
      if (mounted && loading?.key === key) ui.$('vt-readout').textContent = `decoded ${loaded.frames} frames: press Run or Step`;
    } else {
      loaded = await clipFromImages(files, { width: s, height: s });
    }
    if (loaded.frames > frameCount()) {
      const bytes = loaded.width * loaded.height * 4;
      loaded = { ...loaded, frames: frameCount(), rgba: loaded.rgba.slice(0, bytes * frameCount()) };
    }
    return loaded;
  }

  function options() {
    const outFrames = Math.round(Number(ui.$('vt-out-frames').value) || 0);
    const mode = ui.$('vt-mode').value;
    const o = {
      mode,
      placement: ui.$('vt-placement').value,
      seed: ui.seed(),
      refinementPatches: Math.round(Number(ui.$('vt-refine').value) || 0),
      gradientCost: ui.$('vt-gradient').checked,
      blend: ui.$('vt-blend').value,
    };
    if (mode === 'loop') {
      o.transitionWindow = Math.max(3, Math.round(Number(ui.$('vt-window').value) || 60));
      o.transitions = Math.min(16, Math.max(1, Math.round(Number(ui.$('vt-transitions').value) || 3)));
    }
    // A loop (7.A) closes through its transition; k of 7.D is for the other modes.
    if (mode !== 'loop') o.fixedFrames = Math.round(Number(ui.$('vt-fixed').value) || 0);
    // A loop is as long as the transition it finds; the other modes take a length.
    if (outFrames > 0 && mode !== 'loop') o.outputFrames = outFrames;
    if (mode === 'extend') {
      const scale = Number(ui.$('vt-scale').value);
      o.outputWidth = Math.round(scale * size());
      o.outputHeight = Math.round(scale * size());
    }
    return o;
  }

  async function ensureSession() {
    pending ??= (async () => {
      const c = await loadClip();
      const wire = { clip: { width: c.width, height: c.height, frames: c.frames, rgba: c.rgba } };
      const o = options();
      const made = await remoteSession('VideoTextures', [wire, o], wanted);
      made.mode = o.mode;
      return made;
    })();
    const current = pending;
    try {
      const created = await current;
      if (pending !== current) return null;
      if (session !== created && anatomyOn()) await created.send('setAnatomy', true);
      session = created;
      return session;
    } catch (error) {
      if (pending === current) pending = null;
      throw error;
    }
  }

  const frameImage = (bytes, width, height) =>
    new ImageData(new Uint8ClampedArray(bytes.buffer, bytes.byteOffset, bytes.length), width, height);

  /** The output frame `t` with its seams drawn over it, on the main canvas. */
  async function drawFrame(t) {
    const { width, height } = session;
    const [frame, seams] = await Promise.all([session.send('frame', t), session.send('seams', t)]);
    const canvas = ui.outputCanvas;
    if (canvas.width !== width || canvas.height !== height) {
      canvas.width = width;
      canvas.height = height;
    }
    const ctx = canvas.getContext('2d');
    ctx.putImageData(frameImage(frame, width, height), 0, 0);
    const layer = document.createElement('canvas');
    layer.width = width;
    layer.height = height;
    layer.getContext('2d').putImageData(frameImage(seams, width, height), 0, 0);
    ctx.drawImage(layer, 0, 0);
    shownFrame = t;
    document.body.dataset.videoShownFrame = String(t);
    document.body.dataset.videoSeamPixels = String(seamPixels(seams));
  }

  /**
   * The frame of a loop's seam window (frames 0 to `last`) whose seam overlay has the most seam
   * pixels: 7.A's seam surface crosses each pixel at its own frame, so a fixed frame may show
   * none of it.
   */
  async function busiestSeamFrame(last) {
    let best = 0;
    let most = -1;
    for (let t = 0; t <= last; t++) {
      const count = seamPixels(await session.send('seams', t));
      if (count > most) [best, most] = [t, count];
    }
    return best;
  }

  /** Pixels of a seam overlay that show a seam (spatial or temporal). */
  function seamPixels(overlay) {
    let count = 0;
    for (let i = 3; i < overlay.length; i += 4) if (overlay[i] > 0) count++;
    return count;
  }

  /** The x-t slice at the chosen row: x across, one line per frame, seams drawn. */
  async function drawSlice() {
    if (!session) return;
    const frames = session.getter('frames');
    const row = Math.min(session.height - 1, Number(ui.$('vt-row').value));
    const slice = await session.send('sliceXt', row);
    const canvas = ui.$('vt-slice');
    canvas.width = session.width;
    canvas.height = frames;
    canvas.getContext('2d').putImageData(frameImage(slice, session.width, frames), 0, 0);
    ui.$('vt-slice-caption').textContent = `x-t slice at row ${row} (x across, frames 1-${frames} down), seams in red`;
  }

  async function drawLoopPoint(loopFrame) {
    const frames = session.getter('frames');
    const last = loopFrame >= 0 ? loopFrame : frames - 1;
    const first = (last + 1) % frames;
    const [a, b] = await Promise.all([session.send('frame', last), session.send('frame', first)]);
    show(ui.$('vt-loop-last'), frameImage(a, session.width, session.height));
    show(ui.$('vt-loop-first'), frameImage(b, session.width, session.height));
    ui.$('vt-loop-caption').textContent = loopFrame >= 0
      ? `Where the loop closes (the centre of the seam window of 7.A, or the end of a 7.D loop): frame ${last + 1} is followed by frame ${first + 1}.`
      : `Not a loop: frame ${last + 1} is followed by frame ${first + 1} only when played round.`;
  }

  async function collectOutput() {
    const frames = session.getter('frames');
    output = [];
    for (let t = 0; t < frames; t++) output.push(frameImage(await session.send('frame', t), session.width, session.height));
    ui.$('vt-playback-caption').textContent = `output: ${session.width}×${session.height}, ${frames} frames, looping`;
    document.body.dataset.videoFrames = String(frames);
    // The baseline: a loop as long as the output, cut from the clip and closed by a cross-fade.
    baseline = crossfadeLoop(inputFrames, frames);
    ui.$('vt-crossfade-caption').textContent = baseline.length > 1
      ? `cross-fade loop (baseline): ${baseline.length} frames, the first ${fadeFrames(baseline.length)} blended`
      : 'cross-fade loop (baseline): the clip is too short';
    document.body.dataset.videoBaselineFrames = String(baseline.length);
  }

  function startPlayback() {
    if (playTimer) return;
    playTimer = setInterval(() => {
      if (recording) return;
      playIndex++;
      if (output.length > 0) show(ui.$('vt-playback'), output[playIndex % output.length]);
      if (inputFrames.length > 0) show(ui.$('vt-input'), inputFrames[playIndex % inputFrames.length]);
      if (baseline.length > 0) show(ui.$('vt-crossfade'), baseline[playIndex % baseline.length]);
      if (output.length > 0) document.body.dataset.videoPlayed = String(playIndex);
    }, 1000 / PLAYBACK_FPS);
  }

  async function record() {
    if (output.length < 2 || recording) return;
    recording = true;
    try {
      // Twice round, so the video itself shows the loop point.
      await recordToLink({
        canvas: ui.$('vt-playback'), frames: [...output, ...output], fps: PLAYBACK_FPS, show,
        button: ui.$('vt-record'), link: ui.$('vt-download'),
        describe: (blob) => `download video (${output.length} frames twice, ${(blob.size / 1024).toFixed(0)} KB WebM)`,
      });
    } catch (error) {
      ui.$('vt-readout').textContent = `recording failed: ${error.message ?? error}`;
    } finally {
      recording = false;
    }
  }

  return {
    id,
    title,
    optionsHtml: OPTIONS_HTML,
    sideHtml: SIDE_HTML,
    ownsOutputSize: "the video's frames take this panel's own size field (a spatial extension is a multiple of it: extend ×)",
    mount() {
      // Each control is live only in the modes that read it.
      const syncMode = () => {
        const loop = ui.$('vt-mode').value === 'loop';
        ui.$('vt-window').disabled = !loop;
        ui.$('vt-transitions').disabled = !loop;
        ui.$('vt-scale').disabled = ui.$('vt-mode').value !== 'extend';
        ui.$('vt-fixed').disabled = loop;
        ui.$('vt-fixed-label').title = loop ? `${FIXED_TITLE}. Off: a loop (7.A) closes through its transition` : FIXED_TITLE;
      };
      ui.$('vt-mode').addEventListener('change', syncMode);
      syncMode();
      ui.$('vt-record').addEventListener('click', record);
      ui.$('vt-anatomy-on').addEventListener('change', toggleAnatomy);
      ui.$('vt-row').addEventListener('input', () => drawSlice().catch(() => {}));
      ui.$('vt-source').addEventListener('change', () => {
        if (ui.$('vt-source').value === 'file') ui.$('vt-file').click();
      });
      ui.$('vt-file').addEventListener('change', () => {
        ui.$('vt-source').value = 'file';
        clip = null;
        this.reset();
      });
      startPlayback();
    },
    unmount() {
      mounted = false;
      clearInterval(playTimer);
      playTimer = null;
    },
    async step() {
      const current = await ensureSession();
      if (!current || current.done) return null;
      const event = await current.step();
      return current === session ? event : null;
    },
    onStep(event) {
      // The runner does not wait for drawing; a failed fetch is shown, not thrown. The promise is
      // for the page's step history, which copies the canvas once the frame is drawn.
      return this.draw(event).catch((error) => { ui.$('vt-readout').textContent = `drawing failed: ${error.message ?? error}`; });
    },
    async draw(event) {
      const frames = session.getter('frames');
      const p = event.patch;
      const loop = session.mode === 'loop';
      // A loop's seams lie in the window around its transition; other modes show the middle of
      // the clip as the new patch placed it.
      const t = loop && event.loopFrame != null && event.patchesPlaced > 1
        ? await busiestSeamFrame(Math.min(frames - 1, 2 * event.loopFrame))
        : Math.min(frames - 1, Math.max(0, (p?.offsetT ?? 0) + Math.floor(clip.frames / 2)));
      ui.$('vt-row').max = String(session.height - 1);
      ui.$('vt-readout').textContent =
        (p ? `patch ${p.index + 1} at (x ${p.offsetX}, y ${p.offsetY}, t ${p.offsetT})` : `${event.patchesPlaced} patches`) +
        ` · ${event.pixelsTaken} voxels taken · ` +
        `cut cost ${event.cutCost.toPrecision(3)}${event.covered ? ' · refining' : ''} · showing frame ${t + 1}/${frames}` +
        transitionText(event);
      await drawFrame(t);
      await drawSlice();
      drawAnatomy(event);
      const matched = ui.$('vt-placement').value === 'entire-patch' ? 'vt-place-entire' : 'vt-place';
      explain(ui.$('vt-explain'), !anatomyOn() ? 'vt-start' : session.result('placementCosts') ? matched : 'vt-place-random');
      document.body.dataset.videoPatches = String(event.patchesPlaced);
      if (event.done) {
        await drawLoopPoint(event.loopFrame ?? -1);
        await collectOutput();
        document.body.dataset.videoDone = 'true';
      }
    },
    reset() {
      pending?.then((s) => s?.free(), () => {});
      pending = null;
      session = null;
      output = [];
      baseline = [];
      playIndex = 0;
      delete document.body.dataset.videoDone;
      delete document.body.dataset.recordedBytes;
      document.body.dataset.videoPatches = '0';
      ui.$('vt-readout').textContent = 'press Run or Step';
      explain(ui.$('vt-explain'), 'vt-start');
      ui.$('gc-anatomy').hidden = !anatomyOn();
      delete document.body.dataset.videoAnatomyPatches;
      ui.$('vt-download').hidden = true;
      for (const id of ['vt-playback', 'vt-slice', 'vt-loop-last', 'vt-loop-first']) {
        const c = ui.$(id);
        c.getContext('2d').clearRect(0, 0, c.width, c.height);
      }
      const ctx = ui.outputCanvas.getContext('2d');
      ctx.clearRect(0, 0, ui.outputCanvas.width, ui.outputCanvas.height);
      loadClip().catch((error) => { if (mounted) ui.$('vt-readout').textContent = error.message; });
    },
  };
}

function framesOf(clip) {
  const bytes = clip.width * clip.height * 4;
  return Array.from({ length: clip.frames }, (_, t) =>
    new ImageData(new Uint8ClampedArray(clip.rgba.buffer, clip.rgba.byteOffset + t * bytes, bytes), clip.width, clip.height));
}

function show(canvas, image) {
  if (canvas.width !== image.width || canvas.height !== image.height) {
    canvas.width = image.width;
    canvas.height = image.height;
  }
  canvas.getContext('2d').putImageData(image, 0, 0);
}
