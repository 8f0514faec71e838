// The "Graph-cut merge" panel (Kwatra et al. 2003, section 6.B): the exemplar and up to seven
// more images, each placed at an (x, y) position, overlap; paint which pixels must come from
// which image, then watch the graph cut lay each image over the earlier ones along the
// cheapest seam that honours the paint. The list of images, its URL field and the paint rule
// are in merge-sources.js.
import { Exemplar } from '../pkg/texsynth.js';
import { drawInto, drawOverlay } from '../lib/canvas.js';
import { explain } from '../lib/explain.js';
import { paintable, unpaintable } from '../lib/keyboard-brush.js';
import { remoteSession } from '../lib/worker.js';
import { ANATOMY_HTML, showPlacementAnatomy } from './graphcut-anatomy.js';
import {
  boxAround, carryPaint, COLOURS, DEFAULT_SOURCES, defaultSource, MAX_SOURCES, mayPaint, paintedPerSource,
  paintInto, parseSources, readSourceRows, removeFromPaint, sampleUrl, serialiseSources,
  showSourceRows, sourceRowsHtml,
} from './merge-sources.js';

// The placement anatomy's graph view without its cost maps: the user placed the images, so no
// offset was searched or drawn.
const GRAPH_HTML = ANATOMY_HTML.replace(/<h3>Where could[\s\S]*?(?=<h3>The graph)/, '');

export const id = 'merge';
export const title = 'Graph-cut merge';

const OPTIONS_HTML = `
  <input id="mg-sources" type="hidden" value="${serialiseSources(DEFAULT_SOURCES)}">
  ${sourceRowsHtml()}
  <span class="views">brush:
    <label><input type="radio" name="mg-brush" class="view" value="0"> erase</label>
    <label>size <input id="mg-size" class="view" type="number" value="6" min="1" max="40" step="1"></label>
  </span>
  <button id="mg-clear" type="button">Clear paint</button>
  <label title="the graph whose minimum cut is the seam, with the paint as its constraint nodes"><input id="mg-anatomy-on" type="checkbox"> graph view</label>`;

const START = 'paint on the image, then Run or Step';

// Every step brings back the result and its seams; the last also how many pixels each source
// gave.
const VIEWS = ['renderInto', 'renderSeamsInto'];

export function createPanel(ui) {
  let merge = null; // the mirror of the merge in the page's worker
  let pending = null;
  let lastEvent = null;
  let sources = DEFAULT_SOURCES.map((s) => ({ ...s }));
  const images = new Map(); // sample id -> its decoded Exemplar
  const loads = new Map(); // sample id -> the promise of its decoding
  let mask = null;
  let layout = null; // the output box around the sources (merge-sources.js boxAround)
  let painting = false;
  let mounted = true;
  const layers = new WeakMap(); // Exemplar -> a canvas with its pixels, for the preview
  const anatomyOn = () => ui.$('mg-anatomy-on')?.checked ?? false;

  const imageOf = (k) => (k === 0 ? ui.exemplar() : images.get(sources[k].sample));
  const ready = () => Boolean(ui.exemplar()) && sources.every((_, k) => imageOf(k));

  /** Fetches and decodes the samples the list names that are not decoded yet. */
  function loadImages() {
    const wanted = new Set(sources.slice(1).map((s) => s.sample));
    return Promise.all([...wanted].map((sample) => {
      if (!loads.has(sample)) {
        const load = (async () => {
          const bytes = new Uint8Array(await (await fetch(sampleUrl(sample))).arrayBuffer());
          const image = Exemplar.fromBytes(bytes);
          // The fetch may end after the panel was left: nothing will draw or free it then.
          if (mounted) images.set(sample, image);
          else image.free();
        })();
        loads.set(sample, load);
        load.catch(() => loads.delete(sample));
      }
      return loads.get(sample);
    }));
  }

  /** The box around the sources, with the image of each; the paint stays where it lies among
   * them (merge-sources.js). */
  function computeLayout() {
    const placed = sources.map((s, k) => ({ x: s.x, y: s.y, image: imageOf(k) }));
    const box = boxAround(placed.map(({ x, y, image }) => ({ x, y, width: image.width, height: image.height })));
    mask = carryPaint(mask, layout, box);
    layout = { ...box, images: placed.map((p) => p.image) };
  }

  /** Writes the list into its URL field and its rows; the field's change resets the panel (the
   * page listens to it) and loads any new image. */
  function commit() {
    const field = ui.$('mg-sources');
    field.value = serialiseSources(sources);
    showSourceRows(ui.$, sources);
    field.dispatchEvent(new Event('change', { bubbles: true }));
  }

  function addSource() {
    if (sources.length >= MAX_SOURCES) return;
    sources.push(defaultSource(sources.length));
    commit();
    ui.$(`mg-source-${sources.length - 1}`).querySelector('.mg-image').focus();
  }

  function removeSource(k) {
    sources.splice(k, 1);
    if (mask) removeFromPaint(mask, k + 1);
    // The brush follows its source up the list; the removed source's brush gives way to image 1's.
    const value = Number(document.querySelector('input[name="mg-brush"]:checked')?.value);
    const brush = value === k + 1 ? 1 : value > k + 1 ? value - 1 : value;
    const radio = document.querySelector(`input[name="mg-brush"][value="${brush}"]`);
    if (radio) radio.checked = true;
    commit();
    // Focus stays in the list: on the row that moved up, or on "Add image".
    const next = ui.$(`mg-source-${k}`);
    (next && !next.hidden ? next.querySelector('.mg-remove') : ui.$('mg-add')).focus();
  }

  /** Frees the merge in the worker (after whatever step is in flight) and forgets it. */
  function drop() {
    pending?.then((m) => m.free(), () => {});
    pending = null;
    merge = null;
    lastEvent = null;
  }

  /** Makes the merge in the page's worker (www/lib/worker.js); `merge` is its mirror. */
  async function build() {
    computeLayout();
    drop();
    const { width, height, rects, images: placed } = layout;
    const constraints = mask;
    const current = (pending = (async () => {
      const calls = () => (anatomyOn() ? ['placementGraph'] : []);
      const wanted = () => ({ views: VIEWS, calls: calls(), finalCalls: [...calls(), 'sourcePixels'] });
      const made = await remoteSession('GraphcutMerge', [{ outputWidth: width, outputHeight: height, gradientCost: true }], wanted);
      if (anatomyOn()) await made.send('setAnatomy', true);
      for (const [k, rect] of rects.entries()) await made.send('addSource', { exemplar: placed[k] }, rect.x, rect.y);
      await made.send('setConstraints', constraints);
      return made;
    })());
    let made;
    try {
      made = await current;
    } catch (error) {
      if (pending !== current) return null; // reset or left while it was being made
      pending = null;
      throw error;
    }
    if (pending !== current) return null;
    merge = made;
    return merge;
  }

  function layerOf(image) {
    if (!layers.has(image)) {
      const layer = document.createElement('canvas');
      drawInto(layer, image);
      layers.set(image, layer);
    }
    return layers.get(image);
  }

  function outlineSource(ctx, k, dash = []) {
    const r = layout.rects[k];
    ctx.save();
    ctx.strokeStyle = `rgb(${COLOURS[k].join(' ')})`;
    ctx.setLineDash(dash);
    ctx.strokeRect(r.x + 0.5, r.y + 0.5, r.width - 1, r.height - 1);
    ctx.restore();
  }

  // A view as the worker sent it (no copy), or a copy of it.
  const view = (name) => merge.imageData(name) ?? ((b) => merge.view(name, b));

  function draw() {
    if (!layout) return;
    const canvas = ui.outputCanvas;
    const { width, height, rects } = layout;
    canvas.width = width;
    canvas.height = height;
    const ctx = canvas.getContext('2d');
    ctx.clearRect(0, 0, width, height);
    if (merge && lastEvent) {
      // The composite so far with its seams; the sources still to come outlined, dashed.
      drawInto(canvas, merge);
      drawOverlay(canvas, width, height, view('renderSeamsInto'));
      if (!merge.done) for (let k = lastEvent.source + 1; k < rects.length; k++) outlineSource(ctx, k, [4, 3]);
    } else {
      // Preview: every source where it is placed, the later ones half-transparent, outlined in
      // its brush colour.
      rects.forEach((r, k) => {
        ctx.globalAlpha = k === 0 ? 1 : 0.55;
        ctx.drawImage(layerOf(layout.images[k]), r.x, r.y);
      });
      ctx.globalAlpha = 1;
      rects.forEach((_, k) => outlineSource(ctx, k));
    }
    drawOverlay(canvas, width, height, (buffer) => paintInto(buffer, mask));
  }

  /** The painted pixels per source, for tests. */
  function showPainted() {
    if (mask) ui.$('mg-readout').dataset.painted = paintedPerSource(mask, sources.length).join(',');
  }

  function paintAt(event) {
    if (!layout) return;
    const canvas = ui.outputCanvas;
    const box = canvas.getBoundingClientRect();
    const x = Math.floor(((event.clientX - box.left) / box.width) * layout.width);
    const y = Math.floor(((event.clientY - box.top) / box.height) * layout.height);
    const value = Number(document.querySelector('input[name="mg-brush"]:checked')?.value ?? 1);
    if (value > sources.length) return;
    const r = Number(ui.$('mg-size').value) || 6;
    for (let dy = -r; dy <= r; dy++) {
      for (let dx = -r; dx <= r; dx++) {
        const px = x + dx;
        const py = y + dy;
        if (dx * dx + dy * dy > r * r || px < 0 || py < 0 || px >= layout.width || py >= layout.height) continue;
        // Paint the merge would refuse is left off (merge-sources.js mayPaint).
        if (value !== 0 && !mayPaint(layout, value, px, py)) continue;
        mask[py * layout.width + px] = value;
      }
    }
    // New paint means a new merge: the old result no longer honours it.
    drop();
    delete document.body.dataset.mergeDone;
    showPainted();
    draw();
  }

  function readout(event) {
    if (!event.done) return `image ${event.source + 1} laid down`;
    const counts = Array.from(merge.result('sourcePixels') ?? []);
    // The pixels each image gave the result, for the reader and for tests.
    ui.$('mg-readout').dataset.sourcePixels = counts.join(',');
    return `merged · cut cost ${event.cutCost.toFixed(2)} · pixels from each image: ${counts.map((n, k) => `${k + 1}: ${n}`).join(' · ')}`;
  }

  return {
    id,
    title,
    optionsHtml: OPTIONS_HTML,
    ownsOutputSize: 'the merge is as large as the box around its images, placed side by side or anywhere',
    ownsSeed: 'the merge places each image where it is and draws nothing at random',
    sideHtml: `<div class="readout" id="mg-readout">${START}</div>
      <div class="explain" id="mg-explain" data-history-text aria-live="polite"></div>
      <p class="legend">Each image has its colour (the swatch in its row): its outline in the preview, and
      the paint for pixels that must come from it. Image 1 is the exemplar; each later image is laid
      over the earlier ones. Red lines: the seams the graph cut chose.</p>
      ${GRAPH_HTML}`,
    mount() {
      const canvas = ui.outputCanvas;
      canvas.onpointerdown = (e) => { painting = true; paintAt(e); };
      canvas.onpointermove = (e) => painting && paintAt(e);
      this.onPointerUp = () => { painting = false; };
      window.addEventListener('pointerup', this.onPointerUp);
      paintable(canvas, 'Paint which image each pixel must come from');
      ui.$('mg-clear').addEventListener('click', () => {
        mask?.fill(0);
        drop();
        delete document.body.dataset.mergeDone;
        showPainted();
        draw();
      });
      // The graph is recorded from the merge's first step: toggling it starts the merge over.
      ui.$('mg-anatomy-on').addEventListener('change', () => this.reset());
      // The field changes from a link (the page's URL state) or from the rows (commit); the
      // page's own listener then resets the panel, and the reset loads any new image.
      const field = ui.$('mg-sources');
      field.addEventListener('change', () => {
        sources = parseSources(field.value);
        showSourceRows(ui.$, sources);
      });
      const list = ui.$('mg-sources-list');
      list.addEventListener('change', (event) => {
        if (!event.target.matches('.mg-image, .mg-x, .mg-y')) return; // the brush radios
        sources = readSourceRows(ui.$);
        commit();
      });
      list.addEventListener('click', (event) => {
        const row = event.target.closest('.mg-remove')?.closest('[data-source]');
        if (row) removeSource(Number(row.dataset.source));
      });
      ui.$('mg-add').addEventListener('click', addSource);
      showSourceRows(ui.$, sources);
    },
    unmount() {
      mounted = false;
      const building = pending;
      drop();
      // The images go once the merge's set-up, which sends them to the worker, is over.
      Promise.resolve(building).catch(() => {}).finally(() => {
        for (const image of images.values()) image.free();
        images.clear();
      });
      const canvas = ui.outputCanvas;
      canvas.onpointerdown = canvas.onpointermove = null;
      window.removeEventListener('pointerup', this.onPointerUp);
      unpaintable(canvas);
    },
    async step() {
      await loadImages();
      if (!mounted || !ready()) return null;
      const current = merge ?? (await build());
      if (!current || current.done) return null;
      const event = await current.step();
      return current === merge ? event : null; // repainted or reset while the step ran
    },
    onStep(event) {
      lastEvent = event;
      draw();
      ui.$('mg-readout').textContent = readout(event);
      explain(ui.$('mg-explain'), event.done ? 'mg-done' : 'mg-start');
      if (anatomyOn()) showPlacementAnatomy(ui.$, null, merge?.result('placementGraph'));
      if (event.done) document.body.dataset.mergeDone = 'true';
    },
    reset() {
      drop();
      const section = ui.$('gc-anatomy');
      if (section) section.hidden = !anatomyOn();
      delete document.body.dataset.mergeDone;
      const readoutEl = ui.$('mg-readout');
      if (!readoutEl) return;
      delete readoutEl.dataset.sourcePixels;
      explain(ui.$('mg-explain'), 'mg-start');
      if (!ready()) {
        readoutEl.textContent = ui.exemplar() ? 'loading the images…' : START;
        // The images decoded, the reset draws them (unless the panel was left meanwhile).
        if (ui.exemplar()) loadImages().then(() => mounted && ready() && this.reset(), (error) => ui.showError(`could not load an image: ${error.message ?? error}`));
        return;
      }
      computeLayout();
      showPainted();
      draw();
      readoutEl.textContent = START;
    },
  };
}
