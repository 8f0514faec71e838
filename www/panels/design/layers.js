// Stage 4 (Shen et al. 2009, section 3.4): fast layer-based design. The base and the reference
// are two layers, each with its own global deformation; a layout says which output pixel takes
// which layer; patches are chosen by the quadtree-pyramid search (or the exhaustive one, to
// compare) and stitched along minimum-cut seams, one row of patches per step.
import { Exemplar } from '../../pkg/texsynth.js';
import { remoteSession } from '../../lib/worker.js';
import { drawInto } from '../../lib/canvas.js';

export const id = 'layers';
export const title = 'Layers';

/** One layer index per output pixel. */
function layout(kind, w, h) {
  const out = new Uint8Array(w * h);
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      let l = 0;
      if (kind === 'halves') l = x >= w / 2 ? 1 : 0;
      else if (kind === 'stripes') l = Math.floor((y / h) * 4) % 2;
      else if (kind === 'circle') l = (x - w / 2) ** 2 + (y - h / 2) ** 2 < (Math.min(w, h) / 3) ** 2 ? 1 : 0;
      out[y * w + x] = l;
    }
  }
  return out;
}

export function createStage({ ui, gallery, readout }) {
  // The design runs in the page's worker (www/lib/worker.js); `design` is its mirror.
  let design = null;
  let generation = 0;
  let started = 0;

  function drop() {
    generation++;
    design?.free();
    design = null;
  }

  async function build() {
    const w = ui.outputWidth();
    const h = ui.outputHeight();
    const made = await remoteSession('LayerDesign', [{
      outputWidth: w,
      outputHeight: h,
      patchSize: Number(ui.$('dl-patch').value),
      search: ui.$('dl-search').value,
      placement: ui.$('dl-placement').value,
      seed: ui.seed(),
    }], { views: ['renderInto'] });
    const kind = ui.$('dl-layout').value;
    const rotate = Number(ui.$('dl-rotate').value);
    await made.send('addLayer', { exemplar: gallery.baseItem.exemplar }, undefined);
    if (kind !== 'one') {
      await made.send('addLayer', { exemplar: gallery.referenceItem.exemplar }, rotate ? { rotate } : undefined);
      await made.send('setLayout', layout(kind, w, h));
    }
    started = performance.now();
    return made;
  }

  return {
    hint: 'layer 1 is the base, layer 2 the reference; pick a layout and press Run',
    optionsHtml: `
      <label>layout <select id="dl-layout" class="view">
        <option value="one">one layer (the base)</option><option value="halves" selected>left | right</option>
        <option value="stripes">stripes</option><option value="circle">circle</option></select></label>
      <label title="global deformation of layer 2: rotation in degrees">layer 2 rotate <input id="dl-rotate" class="view" type="number" value="0" step="any"></label>
      <label title="patch side (the paper uses 32 to 92)">patch <input id="dl-patch" class="view" type="number" value="32" min="8" max="128"></label>
      <label>search <select id="dl-search" class="view"><option value="qtp">quadtree pyramid</option><option value="exhaustive">exhaustive</option></select></label>
      <label>placement <select id="dl-placement" class="view"><option value="logistic">logistic map</option><option value="random">random</option><option value="best">best match</option></select></label>`,
    mount() {
      for (const id of ['dl-layout', 'dl-rotate', 'dl-patch', 'dl-search', 'dl-placement']) {
        ui.$(id).addEventListener('change', () => this.reset());
      }
      this.reset();
    },
    unmount() {
      drop();
    },
    async step() {
      if (!gallery.baseItem) return null;
      const mine = generation;
      if (!design) {
        const made = await build();
        if (mine !== generation) {
          made.free();
          return null;
        }
        design = made;
      }
      if (design.done) return null;
      const event = await design.step();
      return mine === generation ? event : null;
    },
    onStep(event) {
      drawInto(ui.outputCanvas, design);
      const ms = performance.now() - started;
      readout(`row ${event.row + 1}/${event.rows} · ${event.rowPatches} patches in the row, ${event.patchesPlaced} in all · ` +
        `${(event.pixelsCompared / 1e6).toFixed(2)} M pixel differences · boundary SSD ${event.totalSsd.toFixed(1)} · ${ms.toFixed(0)} ms`);
      if (event.done) {
        // The worker sends the design as PNG (its channels kept) for the gallery.
        const label = `S2 · ${ui.$('dl-layout').value} · ${ui.$('dl-search').value}`;
        design.send('toExemplar').then((made) => {
          gallery.add(label, Exemplar.fromBytes(made.png));
          document.body.dataset.layersDone = 'true';
        }, () => {});
      }
    },
    reset() {
      drop();
      delete document.body.dataset.layersDone;
      if (gallery.baseItem) drawInto(ui.outputCanvas, gallery.baseItem.exemplar);
    },
  };
}
