// The "Graphcut textures" panel (Kwatra et al. 2003): every patch placement is drawn as it happens,
// with the new patch's outline, the error region, and toggles for the seams, the seam-cost heat
// map and the label map; the total seam cost is plotted against the number of patches.
import { drawInto, drawOverlay, strokeRect } from '../lib/canvas.js';
import { drawLinePlot } from '../lib/plot.js';
import { showQualityOrWhy } from '../lib/quality.js';
import { explain } from '../lib/explain.js';
import { remoteSession } from '../lib/worker.js';
import { ANATOMY_HTML, showPlacementAnatomy } from './graphcut-anatomy.js';

export const id = 'graphcut';
export const title = 'Graphcut textures';

const OPTIONS_HTML = `
  <label>Placement <select id="gc-placement">
    <option value="entire-patch">entire patch matching</option>
    <option value="sub-patch">sub-patch matching</option>
    <option value="random">random</option>
  </select></label>
  <label title="randomness of the offset choice, exp(-C / (k σ²)); the paper uses 0.001 to 1">k <input id="gc-k" type="number" value="0.01" min="0.001" max="1" step="0.001"></label>
  <label title="patches placed after the output is covered">refine <input id="gc-refine" type="number" value="24" min="0" max="500" step="1"></label>
  <label>Blend <select id="gc-blend">
    <option value="none">none</option><option value="feather">feather</option><option value="spline">multi-resolution spline</option>
  </select></label>
  <label><input id="gc-gradient" type="checkbox"> gradient cost M′</label>
  <label><input id="gc-rotate" type="checkbox"> rotations</label>
  <label><input id="gc-mirror" type="checkbox"> mirrors</label>
  <label title="also take patches from the exemplar scaled by these factors (at most 4, comma-separated), as in the paper's figure of scaled patches">scales <input id="gc-scales" type="text" value="" placeholder="e.g. 0.5, 2" size="9"></label>
  <label title="with scales: smaller scales towards the top of the output, as in the paper's perspective example"><input id="gc-perspective" type="checkbox"> perspective</label>
  <label><input id="gc-tileable" type="checkbox"> tileable</label>
  <span class="views">show:
    <label><input id="gc-seams" class="view" type="checkbox" checked> seams</label>
    <label><input id="gc-heat" class="view" type="checkbox"> seam cost</label>
    <label><input id="gc-labels" class="view" type="checkbox"> labels</label>
    <label title="the cost surface, the probabilities and the graph of each placement"><input id="gc-anatomy-on" class="view" type="checkbox"> placement anatomy</label>
  </span>`;

const SIDE_HTML = `
  <div class="readout" id="gc-readout">press Run or Step</div>
  <div class="explain" id="gc-explain" data-history-text aria-live="polite"></div>
  <canvas id="gc-plot" class="plot" width="296" height="170" aria-label="Seam cost plot"></canvas>
  <p class="quality" id="gc-quality"></p>
  <p class="legend">Outline: the patch just placed (orange) and the error region it had to cover (dashed).</p>
  ${ANATOMY_HTML}`;

// The session runs in the page's worker; these views come back with every step (the overlays only
// while shown, all of them with the last step so that toggles after the run draw at once).
const ALL_VIEWS = ['renderInto', 'renderSeamsInto', 'renderSeamCostInto', 'renderLabelsInto'];

export function createPanel(ui) {
  let session = null;
  let pending = null;
  let lastEvent = null;
  let costs = [];

  function options() {
    return {
      outputWidth: ui.outputWidth(),
      outputHeight: ui.outputHeight(),
      seed: ui.seed(),
      placement: ui.$('gc-placement').value,
      k: Number(ui.$('gc-k').value),
      refinementPatches: Number(ui.$('gc-refine').value),
      blend: ui.$('gc-blend').value,
      gradientCost: ui.$('gc-gradient').checked,
      rotate: ui.$('gc-rotate').checked,
      mirror: ui.$('gc-mirror').checked,
      // Each entry as typed: one that is not a number reaches the session, which names it.
      scales: ui.$('gc-scales').value.split(/[\s,]+/).filter(Boolean).map(Number),
      perspective: ui.$('gc-perspective').checked,
      tileable: ui.$('gc-tileable').checked,
    };
  }

  // A view as the worker sent it (no copy), or a copy of it.
  const view = (name) => session.imageData(name) ?? ((b) => session.view(name, b));

  function draw() {
    if (!session) return;
    const canvas = ui.outputCanvas;
    const { width, height } = session;
    if (ui.$('gc-labels').checked) {
      canvas.width = width;
      canvas.height = height;
      canvas.getContext('2d').clearRect(0, 0, width, height);
      drawOverlay(canvas, width, height, view('renderLabelsInto'));
    } else {
      drawInto(canvas, session);
    }
    if (ui.$('gc-heat').checked) drawOverlay(canvas, width, height, view('renderSeamCostInto'), 0.85);
    if (ui.$('gc-seams').checked) drawOverlay(canvas, width, height, view('renderSeamsInto'));
    if (lastEvent?.patch && !lastEvent.done) {
      strokeRect(canvas, lastEvent.rect, width, height, '#e0a458');
      strokeRect(canvas, lastEvent.region, width, height, '#7fd1ff', [3, 2]);
    }
  }

  const anatomyOn = () => ui.$('gc-anatomy-on').checked;

  function wanted() {
    const views = ['renderInto'];
    if (ui.$('gc-seams').checked) views.push('renderSeamsInto');
    if (ui.$('gc-heat').checked) views.push('renderSeamCostInto');
    if (ui.$('gc-labels').checked) views.push('renderLabelsInto');
    const calls = anatomyOn() ? ['placementCosts', 'placementGraph'] : [];
    return { views, calls, finalViews: ALL_VIEWS, finalCalls: calls };
  }

  /** A view toggled on mid-run is fetched before it is drawn. */
  async function redraw() {
    const missing = wanted().views.filter((v) => !session?.has(v));
    if (session && missing.length) await session.refresh({ views: missing });
    draw();
  }

  /** The anatomy is recorded from the next placement on (the session keeps nothing otherwise). */
  async function toggleAnatomy() {
    ui.$('gc-anatomy').hidden = !anatomyOn();
    if (session) await session.send('setAnatomy', anatomyOn());
    if (!anatomyOn()) return;
    ui.$('gc-graph-readout').textContent = session
      ? 'recorded from the next placement on: press Step'
      : 'press Run or Step';
  }

  /** Draws the last placement's anatomy and leaves its figures on the page for tests. */
  function drawAnatomy() {
    if (!anatomyOn() || !session) return;
    showPlacementAnatomy(ui.$, session.result('placementCosts'), session.result('placementGraph'));
    document.body.dataset.anatomyPatches = String(lastEvent?.patchesPlaced ?? 0);
  }

  return {
    id,
    title,
    optionsHtml: OPTIONS_HTML,
    sideHtml: SIDE_HTML,
    mount() {
      for (const id of ['gc-seams', 'gc-heat', 'gc-labels']) ui.$(id).addEventListener('change', redraw);
      ui.$('gc-anatomy-on').addEventListener('change', toggleAnatomy);
    },
    async step() {
      pending ??= remoteSession('GraphcutTextures', [ui.exemplar(), options()], wanted);
      const current = pending;
      let created;
      try {
        created = await current;
      } catch (error) {
        if (pending === current) pending = null;
        throw error;
      }
      if (pending !== current) return null; // reset while the session was being made
      if (session !== created && anatomyOn()) await created.send('setAnatomy', true);
      session = created;
      if (session.done) return null;
      const event = await session.step();
      return pending === current ? event : null; // reset while the step ran
    },
    onStep(event) {
      // A placement over a covered output is a surrounded region (section 3.2).
      const refining = lastEvent?.covered ?? false;
      explain(ui.$('gc-explain'), event.done ? 'gc-done' : refining ? 'gc-refine' : 'gc-cover');
      lastEvent = event;
      costs.push(event.totalSeamCost);
      draw();
      drawLinePlot(ui.$('gc-plot'), costs, { title: 'total seam cost per patch' });
      drawAnatomy();
      const where = event.patch ? `offset (${event.patch.offsetX}, ${event.patch.offsetY})` : 'no unused offset left';
      ui.$('gc-readout').textContent =
        `${event.patchesPlaced} patches · ${where} · took ${event.pixelsTaken} px · cut ${event.cutCost.toFixed(2)} · ` +
        `total seam cost ${event.totalSeamCost.toFixed(1)} · ${event.covered ? 'covered' : 'covering…'}`;
      document.body.dataset.patches = String(event.patchesPlaced);
      if (event.done) {
        const scored = session;
        showQualityOrWhy(ui.$('gc-quality'), ui.exemplar(), session, () => session === scored).then(() => {
          document.body.dataset.graphcutDone = 'true';
        });
      }
    },
    reset() {
      pending?.then((s) => s.free(), () => {});
      pending = null;
      session = null;
      lastEvent = null;
      costs = [];
      delete document.body.dataset.graphcutDone;
      document.body.dataset.patches = '0';
      ui.$('gc-readout').textContent = 'press Run or Step';
      explain(ui.$('gc-explain'), 'gc-start');
      ui.$('gc-quality').textContent = '';
      drawLinePlot(ui.$('gc-plot'), [], { title: 'total seam cost per patch' });
      ui.outputCanvas.getContext('2d').clearRect(0, 0, ui.outputCanvas.width, ui.outputCanvas.height);
    },
  };
}
