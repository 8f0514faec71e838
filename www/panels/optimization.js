// The "Texture optimization" panel (Kwatra et al. 2005): every EM iteration is drawn as it
// happens, with the energy plot of the paper's Fig. 3 and a teaching view of the neighbourhood
// grid and the chosen exemplar positions. With "paint constraints" on, colour strokes painted on
// the output become soft constraints (section 4) and the synthesis runs on to follow them. A
// guide (optimization-guides.js) steers the M-step towards a target guide: style transfer or a
// gradient.
import { drawInto } from '../lib/canvas.js';
import { drawLinePlot } from '../lib/plot.js';
import { showQualityOrWhy } from '../lib/quality.js';
import { explain } from '../lib/explain.js';
import { paintable, unpaintable } from '../lib/keyboard-brush.js';
import { remoteSession } from '../lib/worker.js';
import { GUIDE_OPTIONS_HTML, createGuides } from './optimization-guides.js';
import {
  STEP_ANATOMY_HTML, drawCollage, drawSideViews, nodeUnderPointer, outlineNode,
} from './optimization-anatomy.js';

export const id = 'optimization';
export const title = 'Texture optimization';

const OPTIONS_HTML = `
  <label>Search <select id="to-search">
    <option value="patchmatch">PatchMatch</option>
    <option value="kmeans-tree">k-means tree</option>
    <option value="exact">exact (slow)</option>
  </select></label>
  <label title="robust exponent: 2 is least squares, 0.8 the paper's IRLS">r <input id="to-r" type="number" value="0.8" min="0.1" max="2" step="0.1"></label>
  <label title="weight of the gradient energy; 0 is off, the paper uses 10">μ <input id="to-mu" type="number" value="0" min="0" max="100" step="1"></label>
  <label title="the M-step's own gradient weight (not in the paper); empty: μ up to 1, then 1. Set it to μ for the paper's single energy: at μ = 10 that search matches by gradient almost alone and colours drift into blotches or washes">M-step μ <input id="to-m-step-mu" type="number" value="" placeholder="auto" min="0" max="100" step="1"></label>
  <label title="EM iterations per level at most">iterations <input id="to-iterations" type="number" value="5" min="1" max="20" step="1"></label>
  <label><input id="to-tileable" type="checkbox"> tileable</label>
  <label><input id="to-teaching" class="view" type="checkbox"> teaching view</label>
  <label title="stop after each half of an EM iteration: the E-step's output, then the M-step's matches"><input id="to-anatomy-on" class="view" type="checkbox"> step anatomy</label>
  <span class="views" title="soft constraints (section 4): paint colours on the output and the synthesis follows them">
    <label><input id="to-paint" class="view" type="checkbox"> paint constraints</label>
    <input id="to-colour" class="view" type="color" value="#c83c28" aria-label="paint colour">
    <label>λ <input id="to-lambda" class="view" type="number" value="2" min="0" max="1000" step="0.5"></label>
    <button id="to-clear-paint" type="button" class="view">Clear paint</button>
  </span>${GUIDE_OPTIONS_HTML}`;

const SIDE_HTML = `
  <div class="readout" id="to-readout">press Run or Step</div>
  <div class="explain" id="to-explain" data-history-text aria-live="polite"></div>
  <canvas id="to-energy" class="plot" width="296" height="170" aria-label="Energy plot"></canvas>
  <p class="legend" id="to-legend"></p>
  <p class="quality" id="to-quality"></p>
  ${STEP_ANATOMY_HTML}`;

/** Creates the panel. `ui` gives the shared controls, canvas and exemplar. */
export function createPanel(ui) {
  // The session runs in the page's worker (www/lib/worker.js); `session` is its mirror, which holds
  // the views of the last step. `pending` is the promise of it while it is being made.
  let session = null;
  let pending = null;
  let offsetImage = null;
  // The painted constraints: colours with alpha as the mask, at output size.
  let paint = null;
  let painting = false;
  const guides = createGuides(ui, ui.showError);

  function options() {
    return {
      outputWidth: ui.outputWidth(),
      outputHeight: ui.outputHeight(),
      seed: ui.seed(),
      search: ui.$('to-search').value,
      r: Number(ui.$('to-r').value),
      mu: Number(ui.$('to-mu').value),
      // Empty: left to the library, whose M-step uses min(μ, 1); μ itself is the paper's EM.
      ...(ui.$('to-m-step-mu').value === '' ? {} : { mStepMu: Number(ui.$('to-m-step-mu').value) }),
      iterations: Number(ui.$('to-iterations').value),
      tileable: ui.$('to-tileable').checked,
    };
  }

  /** What every step brings back from the worker: the teaching view only while it is shown. */
  function wanted() {
    // The teaching view draws the offset map and the grid; the step anatomy needs only the grid
    // and matches (field), so the worker does not render an offset map for it at every step.
    const teaching = ui.$('to-teaching').checked;
    const field = teaching || anatomyOn();
    return {
      views: teaching ? ['renderInto', 'renderOffsetMapInto'] : ['renderInto'],
      calls: field ? ['energyHistory', 'historyLevels', 'field'] : ['energyHistory', 'historyLevels'],
      getters: ['constraintEnergy'],
      finalViews: ['renderInto', 'renderOffsetMapInto'],
      finalCalls: ['energyHistory', 'historyLevels', 'field'],
    };
  }

  async function ensureSession() {
    if (!pending) {
      pending = remoteSession('TextureOptimization', [ui.exemplar(), options()], wanted);
      const current = pending;
      let created;
      try {
        created = await current;
        created.schedulePlan = await created.send('schedule');
        if (anatomyOn()) await created.send('setHalfSteps', true);
        // Guides go in before the first step; a refusal names what it refuses.
        await guides.apply(created);
      } catch (error) {
        if (pending === current) {
          pending = null;
          created?.free().catch(() => {});
        }
        throw error;
      }
      if (pending !== current) return null;
      session = created;
      const plan = session.schedulePlan.map((l) => `1/${l.scale}·${l.neighbourhoodSize}`).join(' → ');
      ui.$('to-legend').textContent = `schedule: ${plan}`;
    }
    const current = pending;
    const created = await current;
    return pending === current ? created : null;
  }

  /** The teaching view toggled on mid-run: fetch it, then draw. */
  async function redraw() {
    if (session && ui.$('to-teaching').checked && !session.has('field')) {
      await session.refresh({ views: ['renderOffsetMapInto'], calls: ['field'] });
    }
    draw();
  }

  function draw() {
    if (!session) return;
    const canvas = ui.outputCanvas;
    const field = session.result('field');
    if (anatomyOn() && field) {
      // After the E-step: the output x. After an M-step: the z_p it chose, pasted in place.
      if (lastHalf === 'e-step') drawInto(canvas, session);
      else drawCollage(canvas, field, ui.$('exemplar-canvas'), session.width, session.height);
      if (hoveredNode >= 0 && hoveredNode < field.columns.length * field.rows.length) {
        outlineNode(canvas, field, hoveredNode);
      }
    } else if (ui.$('to-teaching').checked && field) {
      // The offset map, scaled up without smoothing so the grid can be drawn finer than a pixel.
      offsetImage = offsetImage?.width === session.width && offsetImage.height === session.height
        ? offsetImage : new ImageData(session.width, session.height);
      session.view('renderOffsetMapInto', offsetImage.data);
      const zoom = Math.max(1, Math.floor(512 / Math.max(session.width, session.height)));
      const source = document.createElement('canvas');
      source.width = session.width;
      source.height = session.height;
      source.getContext('2d').putImageData(offsetImage, 0, 0);
      canvas.width = session.width * zoom;
      canvas.height = session.height * zoom;
      const ctx = canvas.getContext('2d');
      ctx.imageSmoothingEnabled = false;
      ctx.drawImage(source, 0, 0, canvas.width, canvas.height);
      drawGrid(canvas, field);
    } else {
      drawInto(canvas, session);
    }
  }

  const anatomyOn = () => ui.$('to-anatomy-on').checked;
  // The half the last step completed ('first-match', 'e-step' or 'm-step') and the hovered node.
  let lastHalf = null;
  let hoveredNode = -1;


  /** The side views of the step anatomy: matches on the exemplar, weights, the hovered node. */
  function drawAnatomy() {
    const field = session?.result('field');
    if (!anatomyOn() || !field) return;
    drawSideViews(sideViews(), field, ui.$('exemplar-canvas'), hoveredNode);
  }

  const sideViews = () => ({ matches: ui.$('to-matches'), weights: ui.$('to-weights'), readout: ui.$('to-node-readout') });

  function hover(event) {
    const field = session?.result('field');
    if (!anatomyOn() || !field) return;
    const node = nodeUnderPointer(event, ui.outputCanvas, field, session.width, session.height);
    if (node === hoveredNode) return;
    hoveredNode = node;
    draw();
    drawAnatomy();
  }

  async function toggleAnatomy() {
    ui.$('to-anatomy').hidden = !anatomyOn();
    if (session) {
      await session.send('setHalfSteps', anatomyOn());
      if (anatomyOn() && !session.has('field')) await session.refresh({ views: ['renderInto'], calls: ['field'] });
    }
    draw();
    drawAnatomy();
  }

  function paintLayer() {
    const [w, h] = [ui.outputWidth(), ui.outputHeight()];
    if (!paint || paint.width !== w || paint.height !== h) {
      paint = document.createElement('canvas');
      paint.width = w;
      paint.height = h;
    }
    return paint;
  }

  /** A soft round brush stroke at the pointer, in output pixels. */
  function paintAt(event) {
    if (!ui.$('to-paint').checked || !session) return;
    const layer = paintLayer();
    const rect = ui.outputCanvas.getBoundingClientRect();
    const x = ((event.clientX - rect.left) / rect.width) * layer.width;
    const y = ((event.clientY - rect.top) / rect.height) * layer.height;
    const radius = Math.max(3, layer.width / 40);
    const ctx = layer.getContext('2d');
    const gradient = ctx.createRadialGradient(x, y, 0, x, y, radius);
    const colour = ui.$('to-colour').value;
    gradient.addColorStop(0, colour);
    gradient.addColorStop(0.6, colour);
    gradient.addColorStop(1, `${colour}00`);
    ctx.fillStyle = gradient;
    ctx.beginPath();
    ctx.arc(x, y, radius, 0, 2 * Math.PI);
    ctx.fill();
    // Show the stroke over the output while painting.
    const view = ui.outputCanvas.getContext('2d');
    view.save();
    view.globalAlpha = 0.6;
    view.drawImage(layer, 0, 0, ui.outputCanvas.width, ui.outputCanvas.height);
    view.restore();
  }

  /** Hands the painted colours to the session and lets the synthesis follow them. */
  function applyPaint() {
    if (!session || !paint) return;
    const data = paint.getContext('2d').getImageData(0, 0, paint.width, paint.height).data;
    // Sent to the worker in order with the steps; a bad lambda comes back as an error.
    // The refresh brings back `done`, which a finished run's constraints turn false again.
    const current = session;
    current.send('setConstraints', new Uint8Array(data.buffer), Number(ui.$('to-lambda').value))
      .then(() => current.refresh({ getters: ['constraintEnergy'] }))
      .then(
      () => {
        document.body.dataset.constraintsSet = String(Number(document.body.dataset.constraintsSet ?? 0) + 1);
        ui.run();
      },
      (error) => {
        ui.$('to-readout').textContent = error.message;
        ui.showError(error.message);
      },
    );
  }

  function plot() {
    const values = Array.from(session.result('energyHistory') ?? []);
    const levels = session.result('historyLevels') ?? [];
    const schedule = session.schedulePlan;
    const markers = [];
    levels.forEach((level, i) => {
      if (i === 0 || levels[i - 1] !== level) {
        const l = schedule[level];
        markers.push({ index: i, label: `1/${l.scale}·${l.neighbourhoodSize}` });
      }
    });
    drawLinePlot(ui.$('to-energy'), values, { markers, title: 'energy per iteration (Fig. 3)' });
  }

  return {
    id,
    title,
    optionsHtml: OPTIONS_HTML,
    sideHtml: SIDE_HTML,
    mount() {
      ui.$('to-teaching').addEventListener('change', redraw);
      ui.$('to-anatomy-on').addEventListener('change', toggleAnatomy);
      const canvas = ui.outputCanvas;
      canvas.onpointerdown = (e) => {
        painting = ui.$('to-paint').checked && !!session;
        paintAt(e);
      };
      canvas.onpointermove = (e) => (painting ? paintAt(e) : hover(e));
      this.onPointerUp = () => {
        if (!painting) return;
        painting = false;
        try {
          applyPaint();
        } catch (error) {
          ui.$('to-readout').textContent = error.message;
          ui.showError(error.message);
        }
      };
      window.addEventListener('pointerup', this.onPointerUp);
      paintable(canvas, 'Paint soft constraints (with "paint" checked)');
      ui.$('to-clear-paint').addEventListener('click', () => {
        paint = null;
        if (session) session.send('clearConstraints').then(() => session?.refresh()).then(draw);
      });
      guides.mount();
    },
    unmount() {
      guides.unmount();
      ui.outputCanvas.onpointerdown = ui.outputCanvas.onpointermove = null;
      unpaintable(ui.outputCanvas);
      window.removeEventListener('pointerup', this.onPointerUp);
    },
    async step() {
      const current = await ensureSession();
      if (!current || current.done) return null;
      const event = await current.step();
      return current === session ? event : null; // reset while the step ran
    },
    onStep(event) {
      lastHalf = event.kind === 'part' && event.phase !== 'm-step' ? event.phase : 'm-step';
      draw();
      plot();
      drawAnatomy();
      document.body.dataset.half = lastHalf;
      // What this step did, in the paper's terms: a level change, an E-step, an M-step.
      const mStep = guides.active() ? 'to-guided-m-step' : 'to-m-step';
      const whole = event.kind === 'level' ? 'to-level' : event.kind === 'done' ? 'to-done' : mStep;
      const part = event.phase === 'start' ? 'to-graphcut-start' : `to-${event.phase}`;
      explain(ui.$('to-explain'), event.kind === 'part' ? part : whole);
      const constraint = paint ? ` · constraint error ${session.getter('constraintEnergy').toPrecision(3)}` : '';
      const guided = guides.active() ? ` · guide: ${guides.describe()}` : '';
      // Large outputs split an iteration over several steps (kind 'part'): say how far it is.
      const PHASES = { 'first-match': 'first M-step', 'e-step': 'E-step', 'm-step': 'M-step' };
      const progress = event.kind !== 'part' ? ''
        : event.phase === 'start' ? ' (making the graph-cut start of the coarsest level)'
        : ` (${PHASES[event.phase] ?? event.phase}, ${Math.round(event.progress * 100)}% of the iteration)`;
      const figures = event.kind === 'part'
        ? ''
        : ` · energy ${event.energy.toPrecision(4)} · ${event.changed} matches changed`;
      ui.$('to-readout').textContent =
        `level ${event.level + 1}/${event.levelCount} · resolution 1/${event.scale} · ` +
        `neighbourhood ${event.neighbourhoodSize}×${event.neighbourhoodSize} · iteration ${event.iteration}${progress}` +
        `${figures}${constraint}${guided}`;
      document.body.dataset.iterations = String(event.totalIterations);
      document.body.dataset.steps = String(Number(document.body.dataset.steps ?? 0) + 1);
      document.body.dataset.stepKind = event.kind;
      if (event.done) {
        const scored = session;
        showQualityOrWhy(ui.$('to-quality'), ui.exemplar(), session, () => session === scored).then(() => {
          document.body.dataset.optimizationDone = 'true';
        });
      }
    },
    reset() {
      pending?.then((s) => s.free(), () => {});
      pending = null;
      session = null;
      paint = null;
      lastHalf = null;
      hoveredNode = -1;
      delete document.body.dataset.optimizationDone;
      document.body.dataset.iterations = '0';
      document.body.dataset.steps = '0';
      ui.$('to-readout').textContent = 'press Run or Step';
      explain(ui.$('to-explain'), guides.active() ? 'to-guided-start' : 'to-start');
      guides.preview();
      ui.$('to-quality').textContent = '';
      ui.$('to-legend').textContent = '';
      drawLinePlot(ui.$('to-energy'), [], { title: 'energy per iteration (Fig. 3)' });
      const ctx = ui.outputCanvas.getContext('2d');
      ctx.clearRect(0, 0, ui.outputCanvas.width, ui.outputCanvas.height);
    },
  };
}

/** Neighbourhood grid X†: every node centre as a dot, and every fourth neighbourhood outlined
 * (w / 4 spacing means those tile the output without overlap). */
function drawGrid(canvas, field) {
  const ctx = canvas.getContext('2d');
  const sx = canvas.width / field.levelWidth;
  const sy = canvas.height / field.levelHeight;
  const w = field.neighbourhoodSize;
  ctx.fillStyle = 'rgba(0,0,0,0.55)';
  for (const y of field.rows) {
    for (const x of field.columns) ctx.fillRect((x + w / 2) * sx - 1, (y + w / 2) * sy - 1, 2, 2);
  }
  ctx.strokeStyle = 'rgba(255,255,255,0.5)';
  field.rows.forEach((y, j) => {
    if (j % 4) return;
    field.columns.forEach((x, i) => {
      if (i % 4) return;
      ctx.strokeRect(x * sx + 0.5, y * sy + 0.5, w * sx - 1, w * sy - 1);
    });
  });
}
