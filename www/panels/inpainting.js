// The "Fill and extend" panel: hole filling (inpainting) and uncrop of the page's exemplar with
// the package's Inpainting session. Paint the hole over the image (pointer or keyboard brush),
// or give the border to add around it, then watch the graph-cut fill place its patches from the
// outside in and the texture optimisation smooth its seams, with the fill's patches as a
// teaching view and the optimisation's energy plotted.
import { extendBorder } from '../pkg/texsynth.js';
import { drawInto } from '../lib/canvas.js';
import { drawLinePlot } from '../lib/plot.js';
import { explain } from '../lib/explain.js';
import { paintable, unpaintable } from '../lib/keyboard-brush.js';
import { remoteSession } from '../lib/worker.js';
import { createHole, drawHole, outline, paintStroke, pointerPixel } from './inpainting-hole.js';

export const id = 'inpainting';
export const title = 'Fill and extend';

const SIDES = ['top', 'right', 'bottom', 'left'];

const OPTIONS_HTML = `
  <span class="views" role="radiogroup" aria-label="Mode">mode:
    <label><input type="radio" name="ip-mode" value="fill" checked> fill a hole</label>
    <label><input type="radio" name="ip-mode" value="uncrop"> uncrop</label>
  </span>
  <span class="views" id="ip-brush-tools">brush:
    <label><input type="radio" name="ip-brush" class="view" value="1" checked> hole</label>
    <label><input type="radio" name="ip-brush" class="view" value="0"> erase</label>
    <label title="brush radius in image pixels">size <input id="ip-size" class="view" type="number" value="6" min="1" max="128" step="1"></label>
    <button id="ip-clear" type="button">Clear hole</button>
  </span>
  <span class="views ip-border" id="ip-border-tools" hidden>border px:
    <label title="sets all four sides">all <input id="ip-border" type="number" value="32" min="0" max="1024" step="1"></label>
    ${SIDES.map((side) => `<label>${side} <input id="ip-${side}" type="number" value="32" min="0" max="1024" step="1"></label>`).join('\n    ')}
  </span>
  <label title="side of the fill's patches (halved while the image has no window that large outside the hole)">patch size <input id="ip-patch" type="number" value="32" min="4" max="256" step="1"></label>
  <label title="after the fill, texture optimisation over the hole with the known pixels held: it smooths the fill's seams"><input id="ip-optimize" type="checkbox" checked> optimise</label>
  <label title="EM iterations per level of the optimisation at most">iterations <input id="ip-iterations" type="number" value="5" min="1" max="20" step="1"></label>
  <label title="each patch of the fill in its own colour, known pixels grey"><input id="ip-patches" class="view" type="checkbox"> fill patches</label>`;

const SIDE_HTML = `
  <div class="readout" id="ip-readout"></div>
  <div class="explain" id="ip-explain" data-history-text aria-live="polite"></div>
  <figure class="ip-before">
    <canvas id="ip-before" width="1" height="1" aria-label="The input with the hole to fill"></canvas>
    <figcaption>The input, with what is to be filled in pink: compare it with the result.</figcaption>
  </figure>
  <canvas id="ip-energy" class="plot" width="296" height="170" aria-label="Energy of the optimisation per iteration"></canvas>
  <p class="legend">Pink: still to fill. Orange outline: the patch just placed; dashed: the region the
  session works on (the hole and a margin of known pixels). <em>fill patches</em> shows each patch of
  the fill in its own colour, the known pixels grey.</p>
  <button id="ip-download" type="button" disabled>Download PNG</button>`;

const PLOT_TITLE = 'optimisation energy per iteration';

export function createPanel(ui) {
  // The session runs in the page's worker; `session` is its mirror, `pending` the promise of it.
  let session = null;
  let pending = null;
  let sessionMask = null; // the mask the session was made with
  let lastEvent = null;
  let energies = [];
  let energyLevels = [];
  // The hole painted in fill mode, and the exemplar it was painted on (a new one clears it).
  let hole = null;
  let holeImage = null;
  // Uncrop: the image in its new border and the border as the mask, or why there is none.
  let extended = null;
  let extendError = null;
  let painting = false;
  let lastPoint = null;
  let redrawQueued = false;

  const mode = () => document.querySelector('input[name="ip-mode"]:checked')?.value ?? 'fill';
  const patchesOn = () => ui.$('ip-patches').checked;

  function options() {
    return {
      seed: ui.seed(),
      patchSize: Number(ui.$('ip-patch').value),
      optimize: ui.$('ip-optimize').checked,
      iterations: Number(ui.$('ip-iterations').value),
    };
  }

  /** The border as typed: a side that is not a whole number reaches extendBorder, which names it. */
  const border = () => Object.fromEntries(SIDES.map((side) => [side, Number(ui.$(`ip-${side}`).value)]));

  function makeExtended() {
    extended?.image.free();
    extended = null;
    extendError = null;
    try {
      extended = extendBorder(ui.exemplar(), border());
    } catch (error) {
      extendError = error.message ?? String(error);
    }
  }

  /** The session's input in the current mode: the image and its mask. */
  function input() {
    if (mode() === 'fill') return { image: ui.exemplar(), mask: hole.mask };
    if (!extended) throw new Error(extendError ?? 'no border to fill');
    return extended;
  }

  /** Every step brings back the image; the patches view while it is shown or the fill runs
   * (its transparent pixels are what is still to fill), and with the last step. */
  function wanted() {
    const views = ['renderInto'];
    if (patchesOn() || lastEvent?.stage !== 'optimization') views.push('renderPatchesInto');
    return { views, getters: ['region'], finalViews: ['renderInto', 'renderPatchesInto'] };
  }

  async function build() {
    const { image, mask } = input();
    const current = (pending = remoteSession('Inpainting', [image, mask, options()], wanted));
    let made;
    try {
      made = await current;
    } catch (error) {
      if (pending === current) pending = null;
      throw error; // the package's message (an empty hole, say), shown by the page
    }
    if (pending !== current) return null; // reset while it was being made (the reset frees it)
    session = made;
    sessionMask = mask;
    return session;
  }

  function drop() {
    pending?.then((s) => s.free(), () => {});
    pending = null;
    session = null;
    lastEvent = null;
    energies = [];
    energyLevels = [];
  }

  /** The input with its hole tinted, on the output canvas and, to compare the result with, on
   * the side's small copy. */
  function drawPreview() {
    paintPreview();
    const canvas = ui.outputCanvas;
    const before = ui.$('ip-before');
    before.width = canvas.width;
    before.height = canvas.height;
    before.getContext('2d').drawImage(canvas, 0, 0);
  }

  function paintPreview() {
    const canvas = ui.outputCanvas;
    const exemplar = ui.exemplar();
    if (!exemplar) return;
    if (mode() === 'fill') {
      drawInto(canvas, exemplar);
      drawHole(canvas, hole.width, hole.height, hole.mask);
    } else if (extended) {
      const { image, mask } = extended;
      drawInto(canvas, image);
      drawHole(canvas, image.width, image.height, mask);
      const b = border();
      outline(canvas, { x: b.left, y: b.top, width: exemplar.width, height: exemplar.height }, image.width, image.height, '#7fd1ff', [4, 3]);
    } else {
      canvas.getContext('2d').clearRect(0, 0, canvas.width, canvas.height);
    }
  }

  function draw() {
    if (!session) return drawPreview();
    const canvas = ui.outputCanvas;
    const { width, height } = session;
    const patches = session.imageData('renderPatchesInto');
    if (patchesOn() && patches) {
      canvas.width = width;
      canvas.height = height;
      canvas.getContext('2d').putImageData(patches, 0, 0);
    } else {
      drawInto(canvas, session);
    }
    if (!session.done && lastEvent?.stage === 'fill') drawHole(canvas, width, height, sessionMask, patches);
    if (session.done || !lastEvent) return;
    const region = session.getter('region');
    if (region) outline(canvas, region, width, height, '#7fd1ff', [4, 3]);
    const patch = lastEvent.patch;
    if (patch) outline(canvas, { x: patch.x, y: patch.y, width: patch.size, height: patch.size }, width, height, '#e0a458');
  }

  /** A view toggled on mid-run is fetched before it is drawn. */
  async function redraw() {
    if (session && patchesOn() && !session.has('renderPatchesInto')) await session.refresh({ views: ['renderInto', 'renderPatchesInto'], getters: ['region'] });
    draw();
  }

  function plot() {
    const markers = [];
    energyLevels.forEach((level, i) => {
      if (i === 0 || energyLevels[i - 1] !== level) markers.push({ index: i, label: `level ${level + 1}` });
    });
    const title = ui.$('ip-optimize').checked ? PLOT_TITLE : 'optimisation off: no energy to plot';
    drawLinePlot(ui.$('ip-energy'), energies, { markers, title });
  }

  function previewReadout() {
    const exemplar = ui.exemplar();
    if (!exemplar) return 'pick an image on the left';
    if (mode() === 'fill') {
      const share = ((100 * hole.pixels) / (hole.width * hole.height)).toFixed(1);
      return hole.pixels
        ? `hole: ${hole.pixels} pixels (${share}% of the image) · paint more, or Run or Step`
        : 'paint the hole over the image (pointer, or focus the image and use the keyboard brush), then Run or Step';
    }
    if (!extended) return `uncrop: ${extendError}`;
    return `uncrop: ${exemplar.width}×${exemplar.height} → ${extended.image.width}×${extended.image.height} · Run or Step`;
  }

  function readout(event) {
    const share = event.holePixels ? Math.round((100 * event.pixelsFilled) / event.holePixels) : 100;
    const filled = `${event.pixelsFilled} / ${event.holePixels} hole pixels filled (${share}%) · ${event.patchesPlaced} patches`;
    if (event.stage === 'fill') {
      const p = event.patch;
      const placed = p ? ` · patch at (${p.x}, ${p.y}) from (${p.sourceX}, ${p.sourceY}), cut ${p.cutCost.toFixed(2)}` : '';
      return `${event.done ? 'done' : 'fill'}${placed} · ${filled}`;
    }
    const level = event.level == null ? '' : ` · level ${event.level + 1}/${event.levelCount}`;
    const iteration = event.iteration == null ? '' : ` · iteration ${event.iteration}${event.kind === 'part' ? ' (part)' : ''}`;
    const energy = event.energy == null ? '' : ` · energy ${event.energy.toPrecision(4)}`;
    return `${event.done ? 'done' : 'optimisation'}${level}${iteration}${energy} · ${filled}`;
  }

  function paintAt(event) {
    if (!hole) return;
    const point = pointerPixel(ui.outputCanvas, event, hole.width, hole.height);
    const value = Number(document.querySelector('input[name="ip-brush"]:checked')?.value ?? 1);
    paintStroke(hole, lastPoint, point, Number(ui.$('ip-size').value) || 6, value);
    lastPoint = point;
    document.body.dataset.holePixels = String(hole.pixels);
    // One redraw per frame however many pointer events come in.
    if (redrawQueued) return;
    redrawQueued = true;
    requestAnimationFrame(() => {
      redrawQueued = false;
      if (session || !hole || mode() !== 'fill') return;
      drawPreview();
      ui.$('ip-readout').textContent = previewReadout();
    });
  }

  function download() {
    const image = session?.imageData('renderInto');
    if (!image) return;
    const canvas = document.createElement('canvas');
    canvas.width = image.width;
    canvas.height = image.height;
    canvas.getContext('2d').putImageData(image, 0, 0);
    canvas.toBlob((blob) => {
      const link = document.createElement('a');
      link.href = URL.createObjectURL(blob);
      link.download = mode() === 'fill' ? 'filled.png' : 'uncropped.png';
      link.click();
      setTimeout(() => URL.revokeObjectURL(link.href), 1000);
    }, 'image/png');
  }

  return {
    id,
    title,
    optionsHtml: OPTIONS_HTML,
    sideHtml: SIDE_HTML,
    ownsOutputSize: 'the output is the image itself (with its new border when uncropping)',
    mount() {
      const canvas = ui.outputCanvas;
      canvas.onpointerdown = (event) => {
        if (mode() !== 'fill' || !hole || event.button !== 0) return;
        // New paint starts over, as Reset does: the run so far filled another hole.
        if (session || pending) ui.$('reset').click();
        painting = true;
        lastPoint = null;
        paintAt(event);
      };
      canvas.onpointermove = (event) => painting && paintAt(event);
      this.onPointerUp = () => {
        painting = false;
        lastPoint = null;
      };
      window.addEventListener('pointerup', this.onPointerUp);
      ui.$('ip-clear').addEventListener('click', () => {
        if (!hole) return;
        if (session || pending) ui.$('reset').click();
        hole = createHole(hole.width, hole.height);
        document.body.dataset.holePixels = '0';
        drawPreview();
        ui.$('ip-readout').textContent = previewReadout();
      });
      // "all" sets the four sides; the page's reset, which follows, reads them.
      ui.$('ip-border').addEventListener('change', () => {
        for (const side of SIDES) ui.$(`ip-${side}`).value = ui.$('ip-border').value;
      });
      ui.$('ip-patches').addEventListener('change', redraw);
      ui.$('ip-download').addEventListener('click', download);
    },
    unmount() {
      drop();
      extended?.image.free();
      extended = null;
      const canvas = ui.outputCanvas;
      canvas.onpointerdown = canvas.onpointermove = null;
      canvas.style.cursor = canvas.style.touchAction = '';
      window.removeEventListener('pointerup', this.onPointerUp);
      unpaintable(canvas);
    },
    async step() {
      if (!ui.exemplar()) return null;
      const current = session ?? (await build());
      if (!current || current.done) return null;
      const event = await current.step();
      return current === session ? event : null; // reset while the step ran
    },
    onStep(event) {
      lastEvent = event;
      if (event.stage === 'optimization' && event.energy != null && event.kind !== 'part') {
        energies.push(event.energy);
        energyLevels.push(event.level);
      }
      draw();
      plot();
      ui.$('ip-readout').textContent = readout(event);
      explain(ui.$('ip-explain'), event.done ? 'ip-done' : event.stage === 'fill' ? 'ip-fill' : 'ip-optimization');
      ui.$('ip-download').disabled = !event.done;
      Object.assign(document.body.dataset, {
        inpaintingStage: event.stage,
        inpaintingPatches: String(event.patchesPlaced),
        inpaintingFilled: String(event.pixelsFilled),
        holePixels: String(event.holePixels),
      });
      if (event.done) document.body.dataset.inpaintingDone = 'true';
    },
    reset() {
      drop();
      const exemplar = ui.exemplar();
      if (exemplar && exemplar !== holeImage) {
        hole = createHole(exemplar.width, exemplar.height);
        holeImage = exemplar;
      }
      const filling = mode() === 'fill';
      ui.$('ip-brush-tools').hidden = !filling;
      ui.$('ip-border-tools').hidden = filling;
      const canvas = ui.outputCanvas;
      // Painting takes the pointer: a finger paints rather than scrolls the page.
      if (filling) paintable(canvas, 'Paint the hole to fill');
      else unpaintable(canvas);
      canvas.style.cursor = filling ? 'crosshair' : '';
      canvas.style.touchAction = filling ? 'none' : '';
      if (!filling && exemplar) makeExtended();
      if (filling) {
        extended?.image.free();
        extended = null;
      }
      for (const key of ['inpaintingDone', 'inpaintingStage', 'inpaintingPatches', 'inpaintingFilled']) delete document.body.dataset[key];
      const marked = filling ? hole?.pixels : extended?.mask.reduce((n, m) => n + (m ? 1 : 0), 0);
      document.body.dataset.holePixels = String(marked ?? 0);
      ui.$('ip-download').disabled = true;
      ui.$('ip-readout').textContent = previewReadout();
      explain(ui.$('ip-explain'), filling ? 'ip-start' : 'ip-uncrop');
      plot();
      drawPreview();
    },
  };
}
