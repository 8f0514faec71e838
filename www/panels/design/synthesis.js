// Stage 3 (Shen et al. 2009, section 3.3): synthesise a large texture from the base with the
// texture-optimization EM, its M-step distance on pixels or extended by Haar or Daubechies
// wavelet coefficients (eq. 4). "Compare" runs all three on the same base and seed and plots
// their energies together, as in Fig. 5.
import { drawInto } from '../../lib/canvas.js';
import { drawLinePlots } from '../../lib/plot.js';
import { showQuality } from '../../lib/quality.js';
import { remoteSession } from '../../lib/worker.js';

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

  async function start(energy) {
    session?.free();
    session = null;
    current = energy;
    energies[energy] = [];
    base = gallery.baseItem;
    const options = { outputWidth: ui.outputWidth(), outputHeight: ui.outputHeight(), seed: ui.seed(), energy };
    const made = await remoteSession('TextureOptimization', [base.exemplar, options], { views: ['renderInto'] });
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
      <label><input id="dsy-compare" class="view" type="checkbox"> compare all three</label>`,
    sideHtml: `<canvas id="dsy-energy" class="plot" width="296" height="170" aria-label="Energy plot"></canvas>
      <p class="quality" id="dsy-quality"></p>`,
    mount() {
      ui.$('dsy-energy-kind').addEventListener('change', () => this.reset());
      ui.$('dsy-compare').addEventListener('change', () => this.reset());
      this.reset();
    },
    unmount() {
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
      energies[event.energyKind].push(event.energy);
      drawInto(ui.outputCanvas, session);
      plot();
      readout(`${event.energyKind}: level ${event.level + 1}/${event.levelCount} · neighbourhood ` +
        `${event.neighbourhoodSize} · iteration ${event.iteration} · energy ${event.energy.toPrecision(4)}`);
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
      for (const k of Object.keys(energies)) delete energies[k];
      queue = ui.$('dsy-compare')?.checked ? ['pixels', 'haar', 'daubechies'] : [ui.$('dsy-energy-kind')?.value ?? 'pixels'];
      delete document.body.dataset.synthesisDone;
      if (ui.$('dsy-energy')) plot();
      if (gallery.baseItem) drawInto(ui.outputCanvas, gallery.baseItem.exemplar);
    },
  };
}
