// The "Graph-cut merge" panel (Kwatra et al. 2003, section 6.B): the exemplar and a second image
// overlap; paint which pixels must come from which image, then watch the graph cut lay the
// second image over the first along the cheapest seam that honours the paint.
import { Exemplar } from '../pkg/texsynth.js';
import { drawInto, drawOverlay } from '../lib/canvas.js';
import { SAMPLES } from '../lib/samples.js';
import { explain } from '../lib/explain.js';
import { paintable, unpaintable } from '../lib/keyboard-brush.js';
import { remoteSession } from '../lib/worker.js';
import { ANATOMY_HTML, showPlacementAnatomy } from './graphcut-anatomy.js';

// The placement anatomy's graph view without its cost maps: the user placed the image, so no
// offset was searched or drawn.
const GRAPH_HTML = ANATOMY_HTML.replace(/<h3>Where could[\s\S]*?(?=<h3>The graph)/, '');

export const id = 'merge';
export const title = 'Graph-cut merge';

const PAINT = [null, [80, 170, 255, 150], [255, 120, 60, 150]];

export function createPanel(ui) {
  let merge = null; // the mirror of the merge in the page's worker
  let pending = null;
  let second = null;
  let mask = null;
  let layout = null;
  let painting = false;
  let mounted = true;
  const anatomyOn = () => ui.$('mg-anatomy-on')?.checked ?? false;

  function optionsHtml() {
    const choices = SAMPLES.map((s) => `<option value="${s.url}" ${s.id === 'sand_128' ? 'selected' : ''}>${s.label}</option>`).join('');
    return `
      <label>Second image <select id="mg-second">${choices}</select></label>
      <label title="horizontal position of the second image">offset x <input id="mg-offset" type="number" value="64" min="0" max="512" step="1"></label>
      <span class="views">brush:
        <label><input type="radio" name="mg-brush" class="view" value="1" checked> first</label>
        <label><input type="radio" name="mg-brush" class="view" value="2"> second</label>
        <label><input type="radio" name="mg-brush" class="view" value="0"> erase</label>
        <label>size <input id="mg-size" class="view" type="number" value="6" min="1" max="40" step="1"></label>
      </span>
      <button id="mg-clear" type="button">Clear paint</button>
      <label title="the graph whose minimum cut is the seam, with the paint as its constraint nodes"><input id="mg-anatomy-on" type="checkbox"> graph view</label>`;
  }

  async function loadSecond() {
    const bytes = new Uint8Array(await (await fetch(ui.$('mg-second').value)).arrayBuffer());
    second?.free();
    second = Exemplar.fromBytes(bytes);
  }

  function computeLayout() {
    const first = ui.exemplar();
    const offset = Math.max(0, Math.round(Number(ui.$('mg-offset').value)) || 0);
    const width = Math.max(first.width, offset + second.width);
    const height = Math.max(first.height, second.height);
    if (!layout || layout.width !== width || layout.height !== height || layout.offset !== offset) {
      layout = { width, height, offset };
      mask = new Uint8Array(width * height);
    }
  }

  /** Frees the merge in the worker (after whatever step is in flight) and forgets it. */
  function drop() {
    pending?.then((m) => m.free(), () => {});
    pending = null;
    merge = null;
  }

  /** Makes the merge in the page's worker (www/lib/worker.js); `merge` is its mirror. */
  async function build() {
    computeLayout();
    drop();
    const current = (pending = (async () => {
      const wanted = () => ({ views: ['renderInto', 'renderSeamsInto'], calls: anatomyOn() ? ['placementGraph'] : [] });
      const made = await remoteSession('GraphcutMerge', [{ outputWidth: layout.width, outputHeight: layout.height, gradientCost: true }], wanted);
      if (anatomyOn()) await made.send('setAnatomy', true);
      await made.send('addSource', { exemplar: ui.exemplar() }, 0, 0);
      await made.send('addSource', { exemplar: second }, layout.offset, 0);
      await made.send('setConstraints', mask);
      return made;
    })());
    const made = await current;
    if (pending !== current) return null;
    merge = made;
    return merge;
  }

  function draw() {
    const canvas = ui.outputCanvas;
    if (!layout) return;
    canvas.width = layout.width;
    canvas.height = layout.height;
    const ctx = canvas.getContext('2d');
    ctx.clearRect(0, 0, layout.width, layout.height);
    if (merge && merge.done) {
      drawInto(canvas, merge);
      drawOverlay(canvas, layout.width, layout.height, (b) => merge.view('renderSeamsInto', b));
    } else {
      // Preview: both sources where they are placed, the second half-transparent.
      for (const [source, x, alpha] of [[ui.exemplar(), 0, 1], [second, layout.offset, 0.55]]) {
        const layer = document.createElement('canvas');
        drawInto(layer, source);
        ctx.globalAlpha = alpha;
        ctx.drawImage(layer, x, 0);
        ctx.globalAlpha = 1;
      }
    }
    drawOverlay(canvas, layout.width, layout.height, (buffer) => {
      mask.forEach((m, i) => PAINT[m] && buffer.set(PAINT[m], i * 4));
    });
  }

  /**
   * Whether a pixel may be painted for image `value` (1: the first, 2: the second): inside that
   * image, and for the second not on its edge where the first image lies on both sides (the merge
   * refuses such paint: the seam cannot reach it). The brush leaves such pixels unpainted.
   */
  function mayPaint(value, x, y) {
    const first = ui.exemplar();
    const rects = [null, [0, 0, first.width, first.height], [layout.offset, 0, second.width, second.height]];
    const inside = (k, px, py) => {
      const [rx, ry, rw, rh] = rects[k];
      return px >= rx && py >= ry && px < rx + rw && py < ry + rh;
    };
    if (!inside(value, x, y)) return false;
    if (value === 1 || !inside(1, x, y)) return true;
    return ![[1, 0], [-1, 0], [0, 1], [0, -1]].some(([dx, dy]) => {
      const nx = x + dx;
      const ny = y + dy;
      const inOutput = nx >= 0 && ny >= 0 && nx < layout.width && ny < layout.height;
      return inOutput && !inside(2, nx, ny) && inside(1, nx, ny);
    });
  }

  function paintAt(event) {
    const canvas = ui.outputCanvas;
    const box = canvas.getBoundingClientRect();
    const x = Math.floor(((event.clientX - box.left) / box.width) * layout.width);
    const y = Math.floor(((event.clientY - box.top) / box.height) * layout.height);
    const value = Number(document.querySelector('input[name="mg-brush"]:checked').value);
    const r = Number(ui.$('mg-size').value) || 6;
    for (let dy = -r; dy <= r; dy++) {
      for (let dx = -r; dx <= r; dx++) {
        const px = x + dx;
        const py = y + dy;
        if (dx * dx + dy * dy > r * r || px < 0 || py < 0 || px >= layout.width || py >= layout.height) continue;
        if (value !== 0 && !mayPaint(value, px, py)) continue;
        mask[py * layout.width + px] = value;
      }
    }
    // New paint means a new merge: the old result no longer honours it.
    drop();
    delete document.body.dataset.mergeDone;
    draw();
  }

  return {
    id,
    title,
    get optionsHtml() {
      return optionsHtml();
    },
    ownsOutputSize: 'the merge is as large as the two images side by side',
    ownsSeed: 'the merge places each image where it is and draws nothing at random',
    sideHtml: `<div class="readout" id="mg-readout">paint on the image, then Run or Step</div>
      <div class="explain" id="mg-explain" data-history-text aria-live="polite"></div>
      <p class="legend">Blue paint: must come from the first image (the exemplar). Orange: from the second.
      Red lines: the seam the graph cut chose.</p>
      ${GRAPH_HTML}`,
    mount() {
      const canvas = ui.outputCanvas;
      canvas.onpointerdown = (e) => { painting = true; paintAt(e); };
      canvas.onpointermove = (e) => painting && paintAt(e);
      this.onPointerUp = () => { painting = false; };
      window.addEventListener('pointerup', this.onPointerUp);
      paintable(canvas, 'Paint which image each pixel must come from');
      ui.$('mg-clear').addEventListener('click', () => { mask?.fill(0); drop(); draw(); });
      // The graph is recorded from the merge's first step: toggling it starts the merge over.
      ui.$('mg-anatomy-on').addEventListener('change', () => this.reset());
      ui.$('mg-second').addEventListener('change', async () => { await loadSecond(); layout = null; if (mounted) this.reset(); });
      // The fetch may end after the panel was left, when its elements are gone.
      loadSecond().then(() => mounted && this.reset());
    },
    unmount() {
      mounted = false;
      const canvas = ui.outputCanvas;
      canvas.onpointerdown = canvas.onpointermove = null;
      window.removeEventListener('pointerup', this.onPointerUp);
      unpaintable(canvas);
    },
    async step() {
      if (!second) return null;
      const current = merge ?? (await build());
      if (!current || current.done) return null;
      const event = await current.step();
      return current === merge ? event : null; // repainted or reset while the step ran
    },
    onStep(event) {
      draw();
      ui.$('mg-readout').textContent = event.done
        ? `merged · cut cost ${event.cutCost.toFixed(2)}`
        : `source ${event.source + 1} laid down`;
      explain(ui.$('mg-explain'), event.done ? 'mg-done' : 'mg-start');
      if (anatomyOn()) showPlacementAnatomy(ui.$, null, merge?.result('placementGraph'));
      if (event.done) document.body.dataset.mergeDone = 'true';
    },
    reset() {
      drop();
      const section = ui.$('gc-anatomy');
      if (section) section.hidden = !anatomyOn();
      delete document.body.dataset.mergeDone;
      if (second && ui.exemplar()) {
        computeLayout();
        draw();
      }
      const readout = ui.$('mg-readout');
      if (readout) readout.textContent = 'paint on the image, then Run or Step';
      explain(ui.$('mg-explain'), 'mg-start');
    },
  };
}
