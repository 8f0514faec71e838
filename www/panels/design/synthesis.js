// Stage 3 (Shen et al. 2009, section 3.3): synthesise a large texture from the base with the
// texture-optimization EM, its M-step distance on pixels or extended by Haar or Daubechies
// wavelet coefficients (eq. 4). "Compare" runs all three on the same base and seed and plots
// their energies together, as in Fig. 5.
import { drawInto } from '../../lib/canvas.js';
import { drawLinePlots } from '../../lib/plot.js';
import { showQuality } from '../../lib/quality.js';
import { remoteSession } from '../../lib/worker.js';
import { drawCollage, drawSideViews, nodeUnderPointer, outlineNode } from '../optimization-anatomy.js';

export const id = 'synthesis';
export const title = 'Synthesise';

const COLORS = { pixels: '#e0a458', haar: '#6fb3ff', daubechies: '#8fd18a' };

export function createStage({ ui, gallery, readout }) {
  // The session runs in the page's worker (www/lib/worker.js); `session` is its mirror.
  // `generation` changes on reset, so a step that was in flight then is dropped.
  let session = null;
  let generation = 0;
  let queue = [];
  let current = null;
  let base = null;
  const energies = {};
  // Step anatomy, as on the texture-optimization panel: the base drawn on a canvas of its own
  // (the z_p are copied from it), the half the last step completed and the hovered node.
  const anatomyOn = () => ui.$('dsy-anatomy')?.checked ?? false;
  let baseCanvas = null;
  let lastHalf = null;
  let hovered = -1;

  function drawStep() {
    const field = session?.result('field');
    if (!anatomyOn() || !field) {
      drawInto(ui.outputCanvas, session);
      return;
    }
    if (lastHalf === 'e-step') drawInto(ui.outputCanvas, session);
    else drawCollage(ui.outputCanvas, field, baseCanvas, session.width, session.height);
    if (hovered >= 0 && hovered < field.columns.length * field.rows.length) outlineNode(ui.outputCanvas, field, hovered);
    const views = { matches: ui.$('dsy-matches'), weights: ui.$('dsy-weights'), readout: ui.$('dsy-node') };
    drawSideViews(views, field, baseCanvas, hovered);
  }

  function hover(event) {
    const field = session?.result('field');
    if (!anatomyOn() || !field) return;
    const node = nodeUnderPointer(event, ui.outputCanvas, field, session.width, session.height);
    if (node !== hovered) {
      hovered = node;
      drawStep();
    }
  }

  async function start(energy) {
    session?.free();
    session = null;
    current = energy;
    energies[energy] = [];
    base = gallery.baseItem;
    const options = { outputWidth: ui.outputWidth(), outputHeight: ui.outputHeight(), seed: ui.seed(), energy };
    const wanted = () => (anatomyOn() ? { views: ['renderInto'], calls: ['field'] } : { views: ['renderInto'] });
    const made = await remoteSession('TextureOptimization', [base.exemplar, options], wanted);
    if (anatomyOn()) {
      await made.send('setHalfSteps', true);
      baseCanvas = document.createElement('canvas');
      drawInto(baseCanvas, base.exemplar);
    }
    session = made;
  }

  function drop() {
    generation++;
    session?.free();
    session = null;
  }

  function plot() {
    drawLinePlots(ui.$('dsy-energy'), Object.entries(energies).map(([energy, values]) => ({
      values, color: COLORS[energy], label: energy,
    })), { title: 'texture energy per iteration (Fig. 5)' });
  }

  return {
    hint: 'pick the energy and press Run; "Compare" runs pixels, Haar and Daubechies in turn',
    optionsHtml: `
      <label title="M-step distance: pixels (Kwatra 2005) or with wavelet coefficients (eq. 4)">energy
        <select id="dsy-energy-kind" class="view">
          <option value="pixels">pixels</option><option value="haar">Haar</option><option value="daubechies" selected>Daubechies D4</option>
        </select></label>
      <label><input id="dsy-compare" class="view" type="checkbox"> compare all three</label>
      <label title="stop after each half of an EM iteration: the E-step's output, then the M-step's matches"><input id="dsy-anatomy" class="view" type="checkbox"> step anatomy</label>`,
    sideHtml: `<canvas id="dsy-energy" class="plot" width="296" height="170" aria-label="Energy plot"></canvas>
      <p class="quality" id="dsy-quality"></p>
      <section class="anatomy" id="dsy-anatomy-views" hidden aria-label="Step anatomy">
        <h3>Chosen neighbourhoods z<sub>p</sub> on the base</h3>
        <canvas id="dsy-matches" class="anatomy-graph" width="296" height="296" aria-label="Matched base neighbourhoods"></canvas>
        <h3>IRLS weights <small>section 3.1 of Kwatra et al. 2005</small></h3>
        <canvas id="dsy-weights" class="anatomy-graph" width="296" height="296" aria-label="IRLS weight of each node"></canvas>
        <p class="legend">As on the texture-optimization panel; with a wavelet energy the M-step's distance includes the
          wavelet term (eq. 4), so z<sub>p</sub> can differ from the pixel-nearest one. Hover the output for a node.</p>
        <p class="readout" id="dsy-node" aria-live="polite"></p>
      </section>`,
    mount() {
      ui.$('dsy-energy-kind').addEventListener('change', () => this.reset());
      ui.$('dsy-compare').addEventListener('change', () => this.reset());
      // Half steps are set when a session starts: toggling starts over.
      ui.$('dsy-anatomy').addEventListener('change', () => {
        ui.$('dsy-anatomy-views').hidden = !anatomyOn();
        this.reset();
      });
      ui.outputCanvas.addEventListener('pointermove', hover);
      this.hover = hover;
      this.reset();
    },
    unmount() {
      ui.outputCanvas.removeEventListener('pointermove', this.hover);
      drop();
    },
    async step() {
      if (!gallery.baseItem) return null;
      const mine = generation;
      if (!session) {
        if (queue.length === 0) return null;
        await start(queue.shift());
        if (mine !== generation) return null;
      }
      if (session.done) return null;
      const event = await session.step();
      if (mine !== generation) return null;
      // The run goes on with the next energy when one finishes; the page's done means all ran.
      return { ...event, energyKind: current, done: event.done && queue.length === 0 };
    },
    onStep(event) {
      lastHalf = event.kind === 'part' && event.phase !== 'm-step' ? event.phase : 'm-step';
      document.body.dataset.half = lastHalf;
      // Half steps carry no new energy: the plot gets a point per whole iteration.
      if (event.kind !== 'part') energies[event.energyKind].push(event.energy);
      drawStep();
      plot();
      const half = event.kind === 'part' ? ` · ${event.phase === 'e-step' ? 'E-step' : 'first M-step'} done` : '';
      readout(`${event.energyKind}: level ${event.level + 1}/${event.levelCount} · neighbourhood ` +
        `${event.neighbourhoodSize} · iteration ${event.iteration}${half} · energy ${event.energy.toPrecision(4)}`);
      if (session.done) {
        const last = queue.length === 0;
        const quality = showQuality(ui.$('dsy-quality'), base.exemplar, session);
        const image = new ImageData(session.width, session.height);
        session.renderInto(image.data);
        gallery.add(`S1 · ${event.energyKind}`, gallery.copy({
          toRgba: () => image.data, width: session.width, height: session.height,
        }));
        session.free();
        session = null;
        if (last) quality.then(() => { document.body.dataset.synthesisDone = 'true'; });
      }
    },
    reset() {
      drop();
      lastHalf = null;
      hovered = -1;
      for (const k of Object.keys(energies)) delete energies[k];
      queue = ui.$('dsy-compare')?.checked ? ['pixels', 'haar', 'daubechies'] : [ui.$('dsy-energy-kind')?.value ?? 'pixels'];
      delete document.body.dataset.synthesisDone;
      if (ui.$('dsy-energy')) plot();
      if (gallery.baseItem) drawInto(ui.outputCanvas, gallery.baseItem.exemplar);
    },
  };
}
