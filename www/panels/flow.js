// The "Flow animation" panel (Kwatra et al. 2005, section 4.1): the texture is synthesised frame
// after frame so that it moves along a flow field. The main canvas shows each EM iteration of the
// frame being made; the side shows the finished frames playing in a loop, the naive warp of the
// first frame for comparison (the paper's Fig. 7), the flow as arrows, and the per-frame
// energies. "Record WebM" plays the finished frames through the browser's MediaRecorder. The step
// anatomy (the texture-optimization panel's, optimization-anatomy.js) splits each EM iteration of
// a frame into its E-step and M-step and shows them beside the warped previous frame, the soft
// constraint that makes a frame follow the flow.
import { flowField } from '../pkg/texsynth.js';
import { drawInto } from '../lib/canvas.js';
import { drawLinePlot } from '../lib/plot.js';
import { showQuality } from '../lib/quality.js';
import { explain } from '../lib/explain.js';
import { remoteSession } from '../lib/worker.js';
import { recordToLink } from '../lib/record.js';
import { fieldFromStrokes } from '../lib/flow-drawing.js';
import { paintable, unpaintable } from '../lib/keyboard-brush.js';
import {
  stepAnatomyHtml, drawCollage, drawSideViews, nodeUnderPointer, outlineNode,
} from './optimization-anatomy.js';

export const id = 'flow';
export const title = 'Flow animation';

/** The flows offered, by name; `s` is the strength picked on the page (pixels per frame). */
const FLOWS = {
  vortex: (s) => ({ type: 'vortex', strength: s }),
  sink: (s) => ({ type: 'sink', strength: s / 2 }),
  source: (s) => ({ type: 'source', strength: s / 2 }),
  shear: (s) => ({ type: 'shear', strength: s }),
  translation: (s) => ({ type: 'translation', strength: s, angle: 30 }),
  whirlpool: (s) => ({ components: [{ type: 'vortex', strength: s }, { type: 'sink', strength: s / 3 }] }),
  circling: (s) => ({ type: 'translation', strength: s, turn: 6 }),
  'pulsing vortex': (s) => ({ type: 'vortex', strength: s, period: 40 }),
};

/** The flow choice whose field the user draws on the flow view (section 4.1's interactive flows). */
const DRAWN = 'drawn';

const PLAYBACK_FPS = 12;
/** Finished frames kept for playback and recording (about 4 MB each at 1024x1024). */
const MAX_KEPT_FRAMES = 600;

const OPTIONS_HTML = `
  <label>Flow <select id="fl-flow">
    ${Object.keys(FLOWS).map((name) => `<option value="${name}">${name}</option>`).join('')}
    <option value="${DRAWN}">drawn by hand</option>
  </select></label>
  <label title="pixels per frame at half the frame's shorter side">strength <input id="fl-strength" type="number" value="2" min="0" max="16" step="0.5"></label>
  <label title="weight of the flow term: higher follows the flow more closely, lower keeps the texture sharper">λ <input id="fl-lambda" type="number" value="0.2" min="0" max="100" step="0.05"></label>
  <label>frames <input id="fl-frames" type="number" value="60" min="2" max="600" step="1"></label>
  <label title="match at half-pixel precision: content carried along the flow keeps its fraction of a pixel, so a flow slower than half a pixel per frame (the vortex's centre) moves the texture; a little softer, and under fast turns some textures lose more detail"><input id="fl-subpixel" type="checkbox"> sub-pixel</label>
  <label title="stop after each half of an EM iteration: the E-step's frame, then the M-step's matches, beside the warped previous frame"><input id="fl-anatomy-on" class="view" type="checkbox"> step anatomy</label>
  <button id="fl-record" type="button" class="view">Record WebM</button>
  <a id="fl-download" hidden download="texsynth-flow.webm">download video</a>`;

/** The flow panel's part of the step anatomy: the three images one iteration is about. */
const WARPED_HTML = `
    <h3>One iteration of a frame <small>section 4.1, eq. 3</small></h3>
    <div class="side-row anatomy-triple">
      <figure><canvas id="fl-warped" width="96" height="96" aria-label="Previous frame warped along the flow"></canvas>
        <figcaption>previous frame, warped: the target</figcaption></figure>
      <figure><canvas id="fl-e-step" width="96" height="96" aria-label="Frame after the last E-step"></canvas>
        <figcaption>after the E-step</figcaption></figure>
      <figure><canvas id="fl-m-step" width="96" height="96" aria-label="Neighbourhoods the last M-step chose"></canvas>
        <figcaption>the M-step's z<sub>p</sub></figcaption></figure>
    </div>
    <p class="legend" id="fl-warped-legend">Frame 1 is plain texture optimization: no previous frame yet.</p>`;

const SIDE_HTML = `
  <div class="readout" id="fl-readout">press Run or Step (frames of 128×128 run live; 256×256 at a few per second)</div>
  <div class="explain" id="fl-explain" data-history-text aria-live="polite"></div>
  ${stepAnatomyHtml(WARPED_HTML)}
  <div class="side-row">
    <figure><canvas id="fl-playback" width="128" height="128" aria-label="Finished frames, playing"></canvas>
      <figcaption>finished frames, looping</figcaption></figure>
    <figure><canvas id="fl-naive" width="128" height="128" aria-label="Naive warp"></canvas>
      <figcaption>naive warp (no synthesis)</figcaption></figure>
  </div>
  <p class="quality" id="fl-quality-first"></p>
  <p class="quality" id="fl-quality-last"></p>
  <p class="quality" id="fl-quality-drift"></p>
  <figure><canvas id="fl-arrows" width="140" height="140" aria-label="Flow field"></canvas>
    <figcaption id="fl-arrows-caption">the flow</figcaption></figure>
  <button id="fl-draw-clear" type="button" hidden>Clear the drawn flow</button>
  <canvas id="fl-texture" class="plot" width="296" height="110" aria-label="Texture energy per frame"></canvas>
  <canvas id="fl-flow-energy" class="plot" width="296" height="110" aria-label="Flow energy per frame"></canvas>`;

/** Creates the panel. `ui` gives the shared controls, canvas and exemplar. */
export function createPanel(ui) {
  // The animation runs in the page's worker (www/lib/worker.js); `session` is its mirror.
  let session = null;
  let pending = null;
  let frames = [];
  // Frame 1 and the last frame are scored in the worker (once each: 0.1-0.7 s a frame at 96 to
  // 256 pixels); `scored` counts resets, so figures that arrive after one are dropped.
  let scored = 0;
  let playTimer = null;
  let playIndex = 0;
  let recording = false;

  // Strokes of the drawn flow, each a list of [x, y] in shares of the frame.
  let strokes = [];
  let stroke = null;
  const drawn = () => ui.$('fl-flow').value === DRAWN;
  const strength = () => Number(ui.$('fl-strength').value);
  /** The flow option: a generator description, or the drawn field at the output's size. */
  const spec = () => (drawn()
    ? fieldFromStrokes(strokes, ui.outputWidth(), ui.outputHeight(), strength())
    : FLOWS[ui.$('fl-flow').value](strength()));

  function options() {
    return {
      outputWidth: ui.outputWidth(),
      outputHeight: ui.outputHeight(),
      seed: ui.seed(),
      lambda: Number(ui.$('fl-lambda').value),
      frames: Number(ui.$('fl-frames').value),
      subPixel: ui.$('fl-subpixel').checked,
      flow: spec(),
    };
  }

  /** The pointer on the flow view as shares of the frame. */
  function sharesAt(event) {
    const box = ui.$('fl-arrows').getBoundingClientRect();
    return [(event.clientX - box.left) / box.width, (event.clientY - box.top) / box.height]
      .map((v) => Math.min(1, Math.max(0, v)));
  }

  function drawStart(event) {
    if (!drawn()) return;
    stroke = [sharesAt(event)];
    strokes.push(stroke);
  }

  function drawMove(event) {
    if (!stroke) return;
    const [x, y] = sharesAt(event);
    const [lx, ly] = stroke[stroke.length - 1];
    // Points a fiftieth of the frame apart: enough for a smooth direction, few to sum over.
    if (Math.hypot(x - lx, y - ly) < 0.02) return;
    stroke.push([x, y]);
    drawArrows();
  }

  /** A finished stroke is a new flow: the animation starts over (as any option change does). */
  function drawEnd() {
    if (!stroke) return;
    if (stroke.length < 2) strokes.pop();
    stroke = null;
    ui.$('fl-flow').dispatchEvent(new Event('change'));
  }

  /** The flow view takes strokes (pointer or keyboard) while the drawn flow is chosen. */
  function syncDrawing() {
    const canvas = ui.$('fl-arrows');
    ui.$('fl-draw-clear').hidden = !drawn();
    canvas.classList.toggle('paintable', drawn());
    if (drawn()) paintable(canvas, 'Draw the flow: each stroke is a direction the texture moves');
    else unpaintable(canvas);
  }

  const anatomyOn = () => ui.$('fl-anatomy-on').checked;
  // The last event, the half it completed and the hovered grid node (step anatomy).
  let lastEvent = null;
  let lastHalf = null;
  let hoveredNode = -1;
  // The warped previous frame exists from the step that begins frame 2 (frame index 1) on.
  const warpedAfter = (event) => !!event && (event.frame > 0 || event.frameFinished);

  /** What the worker sends back with each step: the anatomy's field and warped frame when on. */
  function views() {
    const anatomy = anatomyOn();
    return {
      views: ['renderInto', 'renderNaiveInto', ...(anatomy && warpedAfter(lastEvent) ? ['renderWarpedInto'] : [])],
      calls: ['textureEnergyHistory', 'flowEnergyHistory', ...(anatomy ? ['field'] : [])],
      getters: ['frames'],
    };
  }

  async function ensureSession() {
    pending ??= remoteSession('FlowAnimation', [ui.exemplar(), options()], views);
    const current = pending;
    try {
      const created = await current;
      if (pending !== current) return null;
      if (session !== created && anatomyOn()) await created.send('setHalfSteps', true);
      session = created;
      return session;
    } catch (error) {
      if (pending === current) pending = null;
      throw error;
    }
  }

  /** The main canvas: the frame; with the anatomy on, after an M-step the z_p it chose pasted in
   * place (an M-step changes no pixel, so the frame alone would not show what it did). */
  function drawMain() {
    const canvas = ui.outputCanvas;
    const field = session.result('field');
    if (!anatomyOn() || !field || lastHalf === 'e-step') drawInto(canvas, session);
    else drawCollage(canvas, field, ui.$('exemplar-canvas'), session.width, session.height);
    if (anatomyOn() && field && hoveredNode >= 0 && hoveredNode < field.columns.length * field.rows.length) {
      outlineNode(canvas, field, hoveredNode);
    }
  }

  /** The anatomy's side views: warped target, E-step frame, M-step collage, matches, weights. */
  function drawAnatomy() {
    const field = session?.result('field');
    if (!anatomyOn() || !field) return;
    if (lastHalf === 'e-step') drawInto(ui.$('fl-e-step'), session);
    else drawCollage(ui.$('fl-m-step'), field, ui.$('exemplar-canvas'), session.width, session.height);
    if (session.has('renderWarpedInto')) {
      drawInto(ui.$('fl-warped'), {
        width: session.width,
        height: session.height,
        renderInto: (data) => session.view('renderWarpedInto', data),
      });
      ui.$('fl-warped-legend').textContent =
        `Frame ${lastEvent.frame + 1}: each E-step averages the matched neighbourhoods with this target, ` +
        `weighted by λ (eq. 3); checkered where the flow brought nothing in.`;
    }
    const views = { matches: ui.$('to-matches'), weights: ui.$('to-weights'), readout: ui.$('to-node-readout') };
    drawSideViews(views, field, ui.$('exemplar-canvas'), hoveredNode);
  }

  function hover(event) {
    const field = session?.result('field');
    if (!anatomyOn() || !field) return;
    const node = nodeUnderPointer(event, ui.outputCanvas, field, session.width, session.height);
    if (node === hoveredNode) return;
    hoveredNode = node;
    drawMain();
    drawAnatomy();
  }

  /** Half steps from the next step on; the field (and warped frame) fetched if missing. */
  async function toggleAnatomy() {
    ui.$('to-anatomy').hidden = !anatomyOn();
    if (!session) return;
    await session.send('setHalfSteps', anatomyOn());
    if (anatomyOn()) await session.refresh();
    drawMain();
    drawAnatomy();
  }

  /** The flow f_t as arrows on a grid (the field's own scale: one arrow per cell). */
  function drawArrows(t = 0) {
    const canvas = ui.$('fl-arrows');
    const ctx = canvas.getContext('2d');
    ctx.fillStyle = '#101217';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    const cells = 10;
    // A drawn flow is evaluated at the arrows alone (one pixel per cell): the whole field of a
    // large output on every pointer move would hold up the page.
    const [w, h] = drawn() ? [cells, cells] : [ui.outputWidth(), ui.outputHeight()];
    let field;
    try {
      field = drawn() ? fieldFromStrokes(strokes, w, h, strength()) : flowField(spec(), w, h, t);
    } catch (error) {
      ui.$('fl-arrows-caption').textContent = error.message;
      return;
    }
    const sx = canvas.width / w;
    const sy = canvas.height / h;
    let max = 1e-6;
    for (let i = 0; i < field.length; i += 2) max = Math.max(max, Math.hypot(field[i], field[i + 1]));
    const scale = (0.9 * canvas.width) / cells / max;
    ctx.strokeStyle = '#e0a458';
    ctx.lineWidth = 1.2;
    for (let gy = 0; gy < cells; gy++) {
      for (let gx = 0; gx < cells; gx++) {
        const x = Math.floor(((gx + 0.5) * w) / cells);
        const y = Math.floor(((gy + 0.5) * h) / cells);
        const i = (y * w + x) * 2;
        const [vx, vy] = [field[i] * scale, field[i + 1] * scale];
        const [x0, y0] = [x * sx, y * sy];
        arrow(ctx, x0 - vx / 2, y0 - vy / 2, x0 + vx / 2, y0 + vy / 2);
      }
    }
    if (drawn()) {
      ctx.strokeStyle = '#6fb3d2';
      ctx.lineWidth = 2;
      for (const points of strokes) {
        ctx.beginPath();
        points.forEach(([x, y], i) => ctx[i ? 'lineTo' : 'moveTo'](x * canvas.width, y * canvas.height));
        ctx.stroke();
      }
      ui.$('fl-arrows-caption').textContent = strokes.length === 0
        ? 'draw strokes here: the texture will move along them'
        : `the drawn flow (${strokes.length} stroke${strokes.length > 1 ? 's' : ''}): up to ${max.toFixed(2)} px per frame`;
      document.body.dataset.flowStrokes = String(strokes.length);
      return;
    }
    ui.$('fl-arrows-caption').textContent = `the flow at frame ${t + 1}: up to ${max.toFixed(2)} px per frame`;
  }

  function plot() {
    drawLinePlot(ui.$('fl-texture'), Array.from(session?.result('textureEnergyHistory') ?? []), { title: 'texture energy per frame' });
    drawLinePlot(ui.$('fl-flow-energy'), Array.from(session?.result('flowEnergyHistory') ?? []).slice(1), {
      title: 'flow energy per frame (from frame 2)',
      color: '#6fb3d2',
    });
  }

  /**
   * Scores finished frame `index` (frame 1, or the last) with the method-independent metrics,
   * and once both are in, the last frame against frame 1: does the animation keep the detail
   * of its first frame (a frame only warped loses it, see the naive warp)?
   */
  function scoreFrame(index) {
    const first = index === 0;
    const element = ui.$(first ? 'fl-quality-first' : 'fl-quality-last');
    const mine = scored;
    showQuality(element, ui.exemplar(), session).then(() => {
      if (mine !== scored) return;
      element.textContent = `frame ${index + 1}: ${element.textContent}`;
      element.dataset.frame = String(index + 1);
      const a = ui.$('fl-quality-first').dataset;
      const b = ui.$('fl-quality-last').dataset;
      if (!a.flat || !b.flat) return;
      const drift = ui.$('fl-quality-drift');
      const ratio = (name) => Number(b[name]) / Number(a[name]);
      drift.textContent = `frame ${b.frame} against frame 1: flat ×${ratio('flat').toFixed(2)} · ` +
        `coherence ×${ratio('coherence').toFixed(2)} (above 1: further from the exemplar than frame 1: detail lost, ` +
        'or, under a turning flow, features turned and moved off whole pixels, which no exemplar patch is)';
      drift.dataset.flat = String(ratio('flat'));
      drift.dataset.coherence = String(ratio('coherence'));
    }, (error) => {
      // A reset frees the session under a pending score: that failure is expected, and dropped.
      if (mine === scored) element.textContent = `frame ${index + 1}: not scored (${error?.message ?? error})`;
    });
  }

  /** Loops the finished frames on the playback canvas. */
  function startPlayback() {
    if (playTimer) return;
    playTimer = setInterval(() => {
      if (recording || frames.length === 0) return;
      playIndex = (playIndex + 1) % frames.length;
      showFrame(ui.$('fl-playback'), frames[playIndex]);
    }, 1000 / PLAYBACK_FPS);
  }

  async function record() {
    if (frames.length < 2 || recording) return;
    recording = true;
    try {
      await recordToLink({
        canvas: ui.$('fl-playback'), frames, fps: PLAYBACK_FPS, show: showFrame,
        button: ui.$('fl-record'), link: ui.$('fl-download'),
        describe: (blob) => `download video (${frames.length} frames, ${(blob.size / 1024).toFixed(0)} KB WebM)`,
      });
    } catch (error) {
      ui.$('fl-readout').textContent = `recording failed: ${error.message ?? error}`;
    } finally {
      recording = false;
    }
  }

  return {
    id,
    title,
    optionsHtml: OPTIONS_HTML,
    sideHtml: SIDE_HTML,
    mount() {
      ui.$('fl-record').addEventListener('click', record);
      for (const id of ['fl-flow', 'fl-strength']) ui.$(id).addEventListener('change', () => drawArrows());
      const arrows = ui.$('fl-arrows');
      arrows.onpointerdown = drawStart;
      arrows.onpointermove = drawMove;
      this.onPointerUp = drawEnd;
      window.addEventListener('pointerup', this.onPointerUp);
      ui.$('fl-flow').addEventListener('change', syncDrawing);
      ui.$('fl-draw-clear').addEventListener('click', () => {
        strokes = [];
        ui.$('fl-flow').dispatchEvent(new Event('change'));
      });
      syncDrawing();
      ui.$('fl-anatomy-on').addEventListener('change', toggleAnatomy);
      ui.outputCanvas.onpointermove = hover;
      startPlayback();
    },
    unmount() {
      ui.outputCanvas.onpointermove = null;
      window.removeEventListener('pointerup', this.onPointerUp);
      unpaintable(ui.$('fl-arrows'));
      clearInterval(playTimer);
      playTimer = null;
    },
    async step() {
      const current = await ensureSession();
      if (!current || current.done) return null;
      const event = await current.step();
      return current === session ? event : null; // reset while the step ran
    },
    onStep(event) {
      lastEvent = event;
      lastHalf = event.kind === 'part' && event.phase !== 'm-step' ? event.phase : 'm-step';
      document.body.dataset.flowHalf = lastHalf;
      document.body.dataset.flowFrame = String(event.frame);
      document.body.dataset.flowSteps = String(Number(document.body.dataset.flowSteps ?? 0) + 1);
      drawMain();
      drawAnatomy();
      drawInto(ui.$('fl-naive'), {
        width: session.width,
        height: session.height,
        renderInto: (data) => session.view('renderNaiveInto', data),
      });
      if (event.frameFinished) {
        if (frames.length < MAX_KEPT_FRAMES) {
          const image = new ImageData(session.width, session.height);
          session.renderInto(image.data);
          frames.push(image);
        }
        plot();
        if (event.frame > 0) drawArrows(event.frame - 1);
        document.body.dataset.flowFrames = String(event.frame + 1);
        if (event.frame === 0 || event.done) scoreFrame(event.frame);
      }
      // Large frames split an iteration over several steps (kind 'part'): say how far it is.
      const part = event.kind === 'part' ? ` (${event.phase}, ${Math.round(100 * event.progress)}%)` : '';
      const what = event.frame === 0
        ? `frame 1 (full multi-level synthesis) · iteration ${event.iteration}${part}`
        : `frame ${event.frame + 1}/${session.getter('frames')} · neighbourhood ${event.neighbourhoodSize}×${event.neighbourhoodSize} · iteration ${event.iteration}${part}`;
      ui.$('fl-readout').textContent =
        `${what} · texture energy ${event.textureEnergy.toPrecision(3)} · flow energy ${event.flowEnergy.toPrecision(3)}`;
      // With the anatomy on, a later frame's halves have their own text (section 4.1, eq. 3).
      const half = anatomyOn() && event.frame > 0 && !event.frameFinished
        ? (lastHalf === 'e-step' ? 'fl-e-step' : 'fl-m-step')
        : null;
      explain(ui.$('fl-explain'), half ?? (event.frame === 0 ? 'fl-first' : 'fl-frame'));
      if (event.done) document.body.dataset.flowDone = 'true';
    },
    reset() {
      pending?.then((s) => s.free(), () => {});
      pending = null;
      session = null;
      frames = [];
      playIndex = 0;
      lastEvent = null;
      lastHalf = null;
      hoveredNode = -1;
      ui.$('to-anatomy').hidden = !anatomyOn();
      ui.$('fl-warped-legend').textContent = 'Frame 1 is plain texture optimization: no previous frame yet.';
      for (const id of ['fl-warped', 'fl-e-step', 'fl-m-step']) {
        const c = ui.$(id);
        c.getContext('2d').clearRect(0, 0, c.width, c.height);
      }
      scored += 1;
      for (const id of ['fl-quality-first', 'fl-quality-last', 'fl-quality-drift']) {
        const element = ui.$(id);
        element.textContent = '';
        for (const key of Object.keys(element.dataset)) delete element.dataset[key];
      }
      delete document.body.dataset.flowDone;
      delete document.body.dataset.flowHalf;
      delete document.body.dataset.flowFrame;
      document.body.dataset.flowSteps = '0';
      delete document.body.dataset.recordedBytes;
      document.body.dataset.flowFrames = '0';
      ui.$('fl-readout').textContent = 'press Run or Step (frames of 128×128 run live; 256×256 at a few per second)';
      explain(ui.$('fl-explain'), 'fl-first');
      ui.$('fl-download').hidden = true;
      for (const id of ['fl-playback', 'fl-naive']) {
        const c = ui.$(id);
        c.getContext('2d').clearRect(0, 0, c.width, c.height);
      }
      const ctx = ui.outputCanvas.getContext('2d');
      ctx.clearRect(0, 0, ui.outputCanvas.width, ui.outputCanvas.height);
      plot();
      drawArrows();
    },
  };
}

function showFrame(canvas, image) {
  if (canvas.width !== image.width || canvas.height !== image.height) {
    canvas.width = image.width;
    canvas.height = image.height;
  }
  canvas.getContext('2d').putImageData(image, 0, 0);
}

function arrow(ctx, x0, y0, x1, y1) {
  const angle = Math.atan2(y1 - y0, x1 - x0);
  const head = Math.min(4, Math.hypot(x1 - x0, y1 - y0) / 2);
  ctx.beginPath();
  ctx.moveTo(x0, y0);
  ctx.lineTo(x1, y1);
  ctx.lineTo(x1 - head * Math.cos(angle - 0.5), y1 - head * Math.sin(angle - 0.5));
  ctx.moveTo(x1, y1);
  ctx.lineTo(x1 - head * Math.cos(angle + 0.5), y1 - head * Math.sin(angle + 0.5));
  ctx.stroke();
}
