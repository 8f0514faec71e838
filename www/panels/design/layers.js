// Stage 4 (Shen et al. 2009, section 3.4): fast layer-based design. One to six layers, each a
// texture of the gallery with its own global deformation (rotation, scale); a layout says which
// output pixel takes which layer: a preset, or painted over the output with a brush (pointer or
// keyboard). Patches are chosen by the quadtree-pyramid search (or the exhaustive one, to
// compare) and stitched along minimum-cut seams, one row of patches per step. The same texture
// as three layers at scales 0.5, 1 and 2, painted in bands, varies the density of its elements
// across the output (the paper's Fig. 12).
import { Exemplar } from '../../pkg/texsynth.js';
import { remoteSession } from '../../lib/worker.js';
import { drawInto, shownRect } from '../../lib/canvas.js';
import { paintable, unpaintable } from '../../lib/keyboard-brush.js';
import { COLOURS } from '../merge-sources.js';

export const id = 'layers';
export const title = 'Layers';

/** The list takes at most this many layers (LayerDesign itself takes 16). */
export const MAX_LAYERS = 6;

/** The scale factors a layer may take (deformation's range). */
const SCALE_MIN = 0.25;
const SCALE_MAX = 4;

/** The opacity of each layer's colour over the preview of the layout. */
const TINT = 0.45;

/** A new row: layer 1 the base, layer 2 the reference, later ones the base again. */
const defaultRow = (k) => ({ source: k === 1 ? 'reference' : 'base', rotate: 0, scale: 1 });

/**
 * One layer index per output pixel for a preset, over `count` layers: `halves` one column per
 * layer, `stripes` two bands per layer cycling through them, `circle` concentric rings with the
 * last layer in the middle, `one` layer 1 everywhere. With two layers these are left | right,
 * four stripes and a disc of a third of the short side.
 */
export function presetLayout(kind, count, w, h) {
  const out = new Uint8Array(w * h);
  if (count < 2 || kind === 'one') return out;
  const ring = ((Math.min(w, h) / 2) * (count === 2 ? 2 / 3 : 0.9)) / (count - 1);
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      let l = 0;
      if (kind === 'halves') l = Math.min(count - 1, Math.floor((x / w) * count));
      else if (kind === 'stripes') l = Math.floor((y / h) * 2 * count) % count;
      else if (kind === 'circle') l = Math.max(0, count - 1 - Math.floor(Math.hypot(x - w / 2, y - h / 2) / ring));
      out[y * w + x] = l;
    }
  }
  return out;
}

/** How many pixels of `layout` each of `count` layers takes. */
export function pixelsPerLayer(layout, count) {
  const counts = new Array(count).fill(0);
  for (const l of layout) if (l < count) counts[l] += 1;
  return counts;
}

/** The deformation `addLayer` takes for a row: one object per deformation, an array for both. */
export function deformationOf(row) {
  const list = [];
  if (row.rotate) list.push({ rotate: row.rotate });
  if (row.scale !== 1) list.push({ scale: row.scale });
  return list.length === 0 ? undefined : list.length === 1 ? list[0] : list;
}

// The list and the painted layout outlive the stage's tabs: going to another stage and back
// keeps them. A row's source is 'base', 'reference' (whatever the gallery marks B or R) or one
// gallery item.
const kept = { rows: [defaultRow(0), defaultRow(1)], mask: null, width: 0, height: 0, brush: 1 };

const escapeHtml = (text) => String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
const rgb = (k) => `rgb(${COLOURS[k].join(' ')})`;

export function createStage({ ui, gallery, readout }) {
  // The design runs in the page's worker (www/lib/worker.js); `design` is its mirror.
  let design = null;
  let generation = 0;
  let started = 0;
  let painting = false;
  let previewShown = false; // the output canvas shows the preview (not a design)
  let preview = null; // the preview's pixels, redrawn where the brush paints
  const pixelsOf = new WeakMap(); // Exemplar -> its RGBA, for the preview

  const rows = () => kept.rows;
  const layoutKind = () => ui.$('dl-layout')?.value ?? 'halves';
  const painted = () => layoutKind() === 'painted';
  /** The layers a design takes: layer 1 alone for "one layer", else every row. */
  const layersUsed = () => (layoutKind() === 'one' ? 1 : rows().length);

  function itemOf(source) {
    if (source === 'reference') return gallery.referenceItem ?? gallery.baseItem;
    if (source !== 'base' && gallery.items.includes(source)) return source;
    return gallery.baseItem;
  }

  /** The painted layout at the output size: one made of layer 1, or the paint scaled to it. */
  function ensureMask() {
    const w = ui.outputWidth();
    const h = ui.outputHeight();
    if (kept.mask && kept.width === w && kept.height === h) return kept.mask;
    const fresh = new Uint8Array(w * h);
    if (kept.mask) {
      for (let y = 0; y < h; y++) {
        const sy = Math.floor((y * kept.height) / h);
        for (let x = 0; x < w; x++) fresh[y * w + x] = kept.mask[sy * kept.width + Math.floor((x * kept.width) / w)];
      }
    }
    Object.assign(kept, { mask: fresh, width: w, height: h });
    return fresh;
  }

  function currentLayout() {
    return painted() ? ensureMask() : presetLayout(layoutKind(), layersUsed(), ui.outputWidth(), ui.outputHeight());
  }

  function drop() {
    generation++;
    design?.free();
    design = null;
    delete document.body.dataset.layersDone;
    delete document.body.dataset.layersCount;
    delete document.body.dataset.layersLayout;
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
    const used = layersUsed();
    const layout = currentLayout().slice();
    try {
      for (const [k, row] of rows().slice(0, used).entries()) {
        await made.send('addLayer', { exemplar: itemOf(row.source).exemplar }, deformationOf(row)).catch((error) => {
          throw new Error(`layer ${k + 1}: ${error.message ?? error}`);
        });
      }
      if (used > 1) await made.send('setLayout', layout);
    } catch (error) {
      made.free();
      throw error;
    }
    // What the run is made of, for the reader and for tests: the layers and each one's pixels.
    document.body.dataset.layersCount = String(used);
    document.body.dataset.layersLayout = pixelsPerLayer(layout, used).join(',');
    started = performance.now();
    return made;
  }

  /** A function from output pixel (x, y) to the offset of its pixel in the row's texture: the
   * texture tiled, turned and scaled as the row says (the preview's approximation of it). */
  function sampler(row) {
    const exemplar = itemOf(row.source).exemplar;
    if (!pixelsOf.has(exemplar)) pixelsOf.set(exemplar, exemplar.toRgba());
    const rgba = pixelsOf.get(exemplar);
    const { width: sw, height: sh } = exemplar;
    const angle = (row.rotate * Math.PI) / 180;
    const c = Math.cos(angle) / row.scale;
    const s = Math.sin(angle) / row.scale;
    const wrap = (v, n) => ((Math.floor(v) % n) + n) % n;
    return { rgba, at: (x, y) => (wrap(x * s + y * c, sh) * sw + wrap(x * c - y * s, sw)) * 4 };
  }

  /** The preview: each pixel's layer texture under its layer's colour, in `box` or everywhere. */
  function drawPreview(box = null) {
    if (!gallery.baseItem) return;
    const w = ui.outputWidth();
    const h = ui.outputHeight();
    const canvas = ui.outputCanvas;
    if (canvas.width !== w || canvas.height !== h) {
      canvas.width = w;
      canvas.height = h;
    }
    if (!preview || preview.width !== w || preview.height !== h || !previewShown) box = null;
    if (!preview || preview.width !== w || preview.height !== h) preview = new ImageData(w, h);
    const layout = currentLayout();
    const samplers = rows().slice(0, layersUsed()).map(sampler);
    const [x0, y0, x1, y1] = box ?? [0, 0, w, h];
    const out = preview.data;
    for (let y = y0; y < y1; y++) {
      for (let x = x0; x < x1; x++) {
        const i = y * w + x;
        const l = Math.min(layout[i], samplers.length - 1);
        const { rgba, at } = samplers[l];
        const j = at(x, y);
        const colour = COLOURS[l];
        for (let ch = 0; ch < 3; ch++) out[i * 4 + ch] = rgba[j + ch] * (1 - TINT) + colour[ch] * TINT;
        out[i * 4 + 3] = 255;
      }
    }
    canvas.getContext('2d').putImageData(preview, 0, 0, x0, y0, x1 - x0, y1 - y0);
    previewShown = true;
  }

  /** The painted pixels per layer (for tests), and the stage's own account of the list. */
  function describe() {
    const count = rows().length;
    const mask = ensureMask();
    document.body.dataset.layersPainted = pixelsPerLayer(mask, count).join(',');
    const about = ui.$('dl-about');
    if (!about) return;
    const used = layersUsed();
    const list = rows().slice(0, used).map((row, k) => {
      const item = itemOf(row.source);
      const parts = [item?.label ?? '—'];
      if (row.rotate) parts.push(`rotated ${row.rotate}°`);
      if (row.scale !== 1) parts.push(`scaled ×${row.scale}`);
      return `${k + 1}: ${parts.join(', ')}`;
    }).join('; ');
    const layout = currentLayout();
    const shares = pixelsPerLayer(layout, used).map((n, k) => `${k + 1}: ${Math.round((100 * n) / layout.length)}%`).join(', ');
    const how = painted() ? 'painted over the output' : `the preset "${ui.$('dl-layout').selectedOptions[0].textContent}"`;
    about.textContent = `${used} layer${used === 1 ? '' : 's'} (${list}). Layout: ${how}; share of the output per layer ${shares}. ` +
      'Each colour over the output is the layer its pixels take; layers of one texture at scales 0.5, 1 and 2 side by side vary the density of its elements (Fig. 12).';
  }

  function rowsHtml() {
    return rows().map((row, k) => {
      const name = `layer ${k + 1}`;
      const remove = k === 0 ? '' : `<button class="dl-remove" type="button" aria-label="Remove ${name}">remove</button>`;
      return `
      <div data-layer="${k}" role="group" aria-label="${name}" style="display: flex; flex-wrap: wrap; gap: .3rem .8rem; align-items: center">
        <label title="brush: paint pixels that take ${name}"><input type="radio" name="dl-brush" class="view" value="${k + 1}" aria-label="brush: ${name}"${kept.brush === k + 1 ? ' checked' : ''}>
          <span aria-hidden="true" style="display: inline-block; width: .9em; height: .9em; border-radius: 2px; vertical-align: -.1em; background: ${rgb(k)}"></span> ${k + 1}</label>
        <select class="dl-source view" aria-label="${name}: source" style="max-width: 16em">${sourceOptions(row.source)}</select>
        <label title="global deformation of ${name}: rotation in degrees, counter-clockwise">rotate <input class="dl-rotate view" type="number" value="${row.rotate}" step="any" aria-label="${name}: rotate (degrees)"></label>
        <label title="global deformation of ${name}: scale factor, ${SCALE_MIN} to ${SCALE_MAX} (below 1: smaller, denser elements)">scale <input class="dl-scale view" type="number" value="${row.scale}" min="${SCALE_MIN}" max="${SCALE_MAX}" step="any" aria-label="${name}: scale"></label>
        ${remove}
      </div>`;
    }).join('');
  }

  function sourceOptions(source) {
    const selected = typeof source === 'string' ? source : String(gallery.items.indexOf(source));
    const choices = [
      ['base', `B: the base${gallery.baseItem ? ` (${gallery.baseItem.label})` : ''}`],
      ['reference', `R: the reference${gallery.referenceItem ? ` (${gallery.referenceItem.label})` : ''}`],
      ...gallery.items.map((item, i) => [String(i), `${i + 1}: ${item.label}`]),
    ];
    return choices.map(([value, text]) => `<option value="${value}"${value === selected ? ' selected' : ''}>${escapeHtml(text)}</option>`).join('');
  }

  /** Writes the list into its rows; greys "Add layer" at the maximum. */
  function showRows() {
    kept.brush = Math.min(kept.brush, rows().length);
    ui.$('dl-rows').innerHTML = rowsHtml();
    ui.$('dl-add').disabled = rows().length >= MAX_LAYERS;
  }

  /** The gallery's items in every row's source choice (the gallery grows as designs finish). */
  function refreshSources() {
    for (const select of ui.$('dl-rows')?.querySelectorAll('.dl-source') ?? []) {
      const row = rows()[Number(select.closest('[data-layer]').dataset.layer)];
      // A row whose item left the gallery takes the base.
      if (typeof row.source !== 'string' && !gallery.items.includes(row.source)) row.source = 'base';
      select.innerHTML = sourceOptions(row.source);
    }
  }

  /** The row of `select`/`input` as its controls read, the numbers kept in range. */
  function readRow(element) {
    const rowEl = element.closest('[data-layer]');
    const row = rows()[Number(rowEl.dataset.layer)];
    const source = rowEl.querySelector('.dl-source').value;
    row.source = source === 'base' || source === 'reference' ? source : gallery.items[Number(source)] ?? 'base';
    const rotate = Number(rowEl.querySelector('.dl-rotate').value);
    row.rotate = Number.isFinite(rotate) ? rotate : 0;
    const scale = Number(rowEl.querySelector('.dl-scale').value);
    row.scale = Number.isFinite(scale) && scale > 0 ? Math.min(SCALE_MAX, Math.max(SCALE_MIN, scale)) : 1;
    rowEl.querySelector('.dl-rotate').value = String(row.rotate);
    rowEl.querySelector('.dl-scale').value = String(row.scale);
  }

  function paintAt(event) {
    if (!painted() || !gallery.baseItem) return;
    const mask = ensureMask();
    const { width: w, height: h } = kept;
    const box = shownRect(ui.outputCanvas);
    const x = Math.floor(((event.clientX - box.left) / box.width) * w);
    const y = Math.floor(((event.clientY - box.top) / box.height) * h);
    const value = Math.min(kept.brush, rows().length) - 1;
    const r = Math.max(1, Number(ui.$('dl-size').value) || 12);
    for (let dy = -r; dy <= r; dy++) {
      for (let dx = -r; dx <= r; dx++) {
        const px = x + dx;
        const py = y + dy;
        if (dx * dx + dy * dy <= r * r && px >= 0 && py >= 0 && px < w && py < h) mask[py * w + px] = value;
      }
    }
    // New paint means a new design: the old one no longer follows the layout.
    drop();
    drawPreview([Math.max(0, x - r), Math.max(0, y - r), Math.min(w, x + r + 1), Math.min(h, y + r + 1)]);
    describe();
  }

  /** The brush's controls and the canvas's keyboard brush are there in "painted" only. */
  function syncPaintTools() {
    const on = painted();
    ui.$('dl-paint-tools').hidden = !on;
    const canvas = ui.outputCanvas;
    canvas.style.cursor = on ? 'crosshair' : '';
    canvas.style.touchAction = on ? 'none' : '';
    if (on) paintable(canvas, 'Paint which layer each pixel takes');
    else unpaintable(canvas);
  }

  return {
    hint: 'each layer: a texture of the gallery with its own rotation and scale; pick a layout or paint one over the output, then press Run',
    optionsHtml: `
      <fieldset id="dl-layers-list" style="flex: 1 1 100%; min-width: 0; display: grid; gap: .3rem; border: 1px solid var(--line); border-radius: 6px; padding: .3rem .6rem; margin: 0">
        <legend>Layers: brush colour, texture, global deformation</legend>
        <div id="dl-rows" style="display: grid; gap: .3rem"></div>
        <div><button id="dl-add" type="button">Add layer</button></div>
      </fieldset>
      <label>layout <select id="dl-layout" class="view">
        <option value="one">one layer (layer 1)</option><option value="halves" selected>side by side (left | right)</option>
        <option value="stripes">stripes</option><option value="circle">circle (rings)</option>
        <option value="painted">painted</option></select></label>
      <span id="dl-paint-tools" class="views" hidden>
        <label title="brush radius in output pixels">brush <input id="dl-size" class="view" type="number" value="12" min="1" max="80" step="1"></label>
        <button id="dl-clear" type="button" title="every pixel back to layer 1">Clear</button>
      </span>
      <label title="patch side (the paper uses 32 to 92)">patch <input id="dl-patch" class="view" type="number" value="32" min="8" max="128"></label>
      <label>search <select id="dl-search" class="view"><option value="qtp">quadtree pyramid</option><option value="exhaustive">exhaustive</option></select></label>
      <label>placement <select id="dl-placement" class="view"><option value="logistic">logistic map</option><option value="random">random</option><option value="best">best match</option></select></label>`,
    sideHtml: `<p class="legend" id="dl-about" data-history-text></p>`,
    mount() {
      showRows();
      for (const id of ['dl-patch', 'dl-search', 'dl-placement']) {
        ui.$(id).addEventListener('change', () => this.reset());
      }
      ui.$('dl-layout').addEventListener('change', () => {
        syncPaintTools();
        this.reset();
      });
      const list = ui.$('dl-layers-list');
      list.addEventListener('change', (event) => {
        if (event.target.name === 'dl-brush') {
          kept.brush = Number(event.target.value);
          return;
        }
        if (!event.target.matches('.dl-source, .dl-rotate, .dl-scale')) return;
        readRow(event.target);
        this.reset();
      });
      list.addEventListener('click', (event) => {
        const rowEl = event.target.closest('.dl-remove')?.closest('[data-layer]');
        if (!rowEl) return;
        const k = Number(rowEl.dataset.layer);
        rows().splice(k, 1);
        // The removed layer's paint goes to layer 1; the later layers' paint moves up with them.
        const mask = ensureMask();
        for (let i = 0; i < mask.length; i++) {
          if (mask[i] === k) mask[i] = 0;
          else if (mask[i] > k) mask[i] -= 1;
        }
        if (kept.brush === k + 1) kept.brush = 1;
        else if (kept.brush > k + 1) kept.brush -= 1;
        showRows();
        this.reset();
        // Focus stays in the list: on the row that moved up, or on "Add layer".
        (ui.$('dl-rows').querySelector(`[data-layer="${k}"] .dl-remove`) ?? ui.$('dl-add')).focus();
      });
      ui.$('dl-add').addEventListener('click', () => {
        if (rows().length >= MAX_LAYERS) return;
        rows().push(defaultRow(rows().length));
        showRows();
        this.reset();
        ui.$('dl-rows').querySelector(`[data-layer="${rows().length - 1}"] .dl-source`).focus();
      });
      ui.$('dl-clear').addEventListener('click', () => {
        ensureMask().fill(0);
        this.reset();
      });
      const canvas = ui.outputCanvas;
      canvas.onpointerdown = (e) => {
        if (!painted()) return;
        painting = true;
        paintAt(e);
      };
      canvas.onpointermove = (e) => painting && paintAt(e);
      this.onPointerUp = () => { painting = false; };
      window.addEventListener('pointerup', this.onPointerUp);
      syncPaintTools();
      this.reset();
    },
    unmount() {
      drop();
      const canvas = ui.outputCanvas;
      canvas.onpointerdown = canvas.onpointermove = null;
      canvas.style.cursor = canvas.style.touchAction = '';
      window.removeEventListener('pointerup', this.onPointerUp);
      unpaintable(canvas);
    },
    onSelection() {
      // Layers that follow the base or the reference follow the gallery's B and R.
      refreshSources();
      this.reset();
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
      previewShown = false;
      const ms = performance.now() - started;
      const used = layersUsed();
      const layout = painted() ? 'painted layout' : `${layoutKind()} layout`;
      readout(`${used} layer${used === 1 ? '' : 's'} · ${layout} · row ${event.row + 1}/${event.rows} · ${event.rowPatches} patches in the row, ${event.patchesPlaced} in all · ` +
        `${(event.pixelsCompared / 1e6).toFixed(2)} M pixel differences · boundary SSD ${event.totalSsd.toFixed(1)} · ${ms.toFixed(0)} ms`);
      if (event.done) {
        // The worker sends the design as PNG (its channels kept) for the gallery.
        const label = `S2 · ${used} layer${used === 1 ? '' : 's'} · ${layoutKind()} · ${ui.$('dl-search').value}`;
        const mine = generation;
        design.send('toExemplar').then((made) => {
          gallery.add(label, Exemplar.fromBytes(made.png));
          refreshSources();
          if (mine === generation) document.body.dataset.layersDone = 'true';
        }, () => {});
      }
    },
    reset() {
      drop();
      if (!gallery.baseItem || !ui.$('dl-rows')) return;
      refreshSources();
      drawPreview();
      describe();
    },
  };
}
