// Cyclic textures (Shen et al. 2009, section 4): the base is cut open along its most seamless
// line, its old edges are stitched by graph cuts, horizontally then vertically, and the result
// is previewed tiled 3x3. One stitch (one graph cut) per step.
import { Exemplar } from '../../pkg/texsynth.js';
import { drawInto, drawOverlay } from '../../lib/canvas.js';
import { remoteSession } from '../../lib/worker.js';

export const id = 'tileable';
export const title = 'Make tileable';

export function createStage({ ui, gallery, readout }) {
  let result = null;

  function preview(exemplar, seam) {
    const one = document.createElement('canvas');
    drawInto(one, exemplar);
    const canvas = ui.outputCanvas;
    canvas.width = exemplar.width * 3;
    canvas.height = exemplar.height * 3;
    const ctx = canvas.getContext('2d');
    for (let j = 0; j < 3; j++) for (let i = 0; i < 3; i++) ctx.drawImage(one, i * exemplar.width, j * exemplar.height);
    if (seam && ui.$('dt-seams').checked) {
      // The stitches of the middle tile.
      const layer = document.createElement('canvas');
      layer.width = exemplar.width;
      layer.height = exemplar.height;
      const image = new ImageData(exemplar.width, exemplar.height);
      image.data.set(seam);
      layer.getContext('2d').putImageData(image, 0, 0);
      ctx.drawImage(layer, exemplar.width, exemplar.height);
    }
  }

  // The stitching runs in the page's worker (www/lib/worker.js); `session` is its mirror, and the
  // last step brings the result back with it.
  let session = null;
  let generation = 0;
  let started = 0;

  function drop() {
    generation++;
    session?.free();
    session = null;
  }

  async function begin() {
    drop();
    result = null;
    const overlap = Number(ui.$('dt-overlap').value);
    const options = overlap > 0 ? { overlapX: overlap, overlapY: overlap } : undefined;
    started = performance.now();
    return remoteSession('TileableTexture', [gallery.baseItem.exemplar, options], { views: ['renderInto'], finalCalls: ['result'] });
  }

  return {
    hint: 'makes the base tileable, one graph cut per step; the preview shows it tiled 3×3',
    optionsHtml: `
      <label title="overlap of the stitches in pixels; 0 = a sixth of each side, at most 64">overlap <input id="dt-overlap" class="view" type="number" value="0" min="0" max="512"></label>
      <label><input id="dt-seams" class="view" type="checkbox"> show seams</label>
      <button id="dt-make" type="button">Make tileable</button>
      <button id="dt-plain" type="button" title="the base tiled as it is, for comparison">Tile the base as is</button>`,
    mount() {
      ui.$('dt-make').addEventListener('click', () => { this.reset(); ui.run(); });
      ui.$('dt-plain').addEventListener('click', () => {
        if (gallery.baseItem) preview(gallery.baseItem.exemplar, null);
        readout('the base tiled as it is: its edges show as lines');
      });
      ui.$('dt-seams').addEventListener('change', () => result && preview(result.exemplar, result.seam));
      this.reset();
    },
    async step() {
      if (!gallery.baseItem) return null;
      if (!session) {
        const making = begin();
        const mine = generation; // begin() has moved it on; a reset while making moves it again
        const made = await making;
        if (mine !== generation) {
          made.free();
          return null;
        }
        session = made;
      }
      const mine = generation;
      if (session.done) return null;
      const event = await session.step();
      return mine === generation ? event : null;
    },
    onStep(event) {
      const ms = performance.now() - started;
      if (!event.done) {
        drawInto(ui.outputCanvas, session);
        readout(`stitched the ${event.axis === 'x' ? 'left and right' : 'top and bottom'} edges (cut at ${event.cut}) · seam cost ${event.seamCost.toFixed(2)} · ${ms.toFixed(0)} ms`);
        return;
      }
      const sent = session.result('result');
      result = { ...sent, exemplar: Exemplar.fromBytes(sent.exemplar.png) };
      preview(result.exemplar, result.seam);
      readout(`tileable ${result.exemplar.width}×${result.exemplar.height} in ${ms.toFixed(0)} ms · ` +
        `cut at column ${result.cutX}, row ${result.cutY} · seam costs ${result.seamCostX.toFixed(2)} + ${result.seamCostY.toFixed(2)}`);
      gallery.add(`${gallery.baseItem.label} · tileable`, result.exemplar);
      document.body.dataset.tileable = 'true';
    },
    unmount() {
      drop();
    },
    reset() {
      drop();
      result = null;
      delete document.body.dataset.tileable;
      if (gallery.baseItem) drawInto(ui.outputCanvas, gallery.baseItem.exemplar);
    },
  };
}
