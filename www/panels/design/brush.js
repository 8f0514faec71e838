// Stage 2 (Shen et al. 2009, section 3.2): local deformation with a brush. Paint roughly over
// texture elements of the reference (right), then click on the base (the large view) where they
// should go: the two-label graph cut (eqs. 1-3) finds the region and the seam, and the Poisson
// paste puts it in. Brushing plain background over elements removes them (density control).
import { TextureBrush } from '../../pkg/texsynth.js';
import { drawInto, drawOverlay } from '../../lib/canvas.js';
import { paintable, unpaintable } from '../../lib/keyboard-brush.js';

export const id = 'brush';
export const title = 'Brush';

export function createStage({ ui, gallery, readout }) {
  let brush = null;
  let baseIndex = -1;
  let mask = null;
  let painting = false;
  let showLabels = true;

  function ensureBrush() {
    if (!brush || baseIndex !== gallery.base) {
      brush?.free();
      brush = new TextureBrush(gallery.baseItem.exemplar, { nu: Number(ui.$('db-nu').value) });
      baseIndex = gallery.base;
    }
    return brush;
  }

  function referenceCanvas() { return ui.$('db-reference'); }

  function drawReference() {
    const ref = gallery.referenceItem;
    if (!ref) return;
    const canvas = referenceCanvas();
    drawInto(canvas, ref.exemplar);
    if (!mask || mask.length !== ref.exemplar.width * ref.exemplar.height) {
      mask = new Uint8Array(ref.exemplar.width * ref.exemplar.height);
    }
    drawOverlay(canvas, ref.exemplar.width, ref.exemplar.height, (buffer) => {
      mask.forEach((m, i) => m && buffer.set([80, 170, 255, 150], i * 4));
    });
  }

  function drawBase() {
    const b = ensureBrush();
    drawInto(ui.outputCanvas, b);
    if (showLabels && ui.$('db-labels').checked) {
      drawOverlay(ui.outputCanvas, b.width, b.height, (buffer) => b.renderLabelsInto(buffer));
    }
    ui.$('db-undo').disabled = b.undoDepth === 0;
  }

  function paintAt(event) {
    const ref = gallery.referenceItem.exemplar;
    const box = referenceCanvas().getBoundingClientRect();
    const x = Math.floor(((event.clientX - box.left) / box.width) * ref.width);
    const y = Math.floor(((event.clientY - box.top) / box.height) * ref.height);
    const r = Number(ui.$('db-size').value) || 5;
    for (let dy = -r; dy <= r; dy++) {
      for (let dx = -r; dx <= r; dx++) {
        const px = x + dx;
        const py = y + dy;
        if (dx * dx + dy * dy <= r * r && px >= 0 && py >= 0 && px < ref.width && py < ref.height) mask[py * ref.width + px] = 1;
      }
    }
    drawReference();
  }

  /** Places the stroke so that its centre lands where the base was clicked. */
  function placeAt(event) {
    const b = ensureBrush();
    const ref = gallery.referenceItem.exemplar;
    let sx = 0;
    let sy = 0;
    let n = 0;
    mask.forEach((m, i) => {
      if (m) { sx += i % ref.width; sy += Math.floor(i / ref.width); n++; }
    });
    if (n === 0) {
      readout('paint over some texture elements of the reference first');
      return;
    }
    const box = ui.outputCanvas.getBoundingClientRect();
    const x = ((event.clientX - box.left) / box.width) * b.width;
    const y = ((event.clientY - box.top) / box.height) * b.height;
    const start = performance.now();
    try {
      const r = b.stroke(ref, mask, Math.round(x - sx / n), Math.round(y - sy / n));
      const ms = performance.now() - start;
      readout(`stroke: ${r.pixelsTaken} pixels took the reference in a ${r.width}×${r.height} window · ` +
        `E(L) ${r.energy.toFixed(2)} · Poisson ${r.poissonIterations} iterations · ${ms.toFixed(0)} ms`);
      document.body.dataset.strokes = String(b.undoDepth);
      mask.fill(0);
      drawReference();
      showLabels = true;
      drawBase();
    } catch (error) {
      readout(error.message);
    }
  }

  return {
    hint: 'paint over elements of the reference (right), then click on the base where they should go',
    optionsHtml: `
      <label title="brush radius in reference pixels">brush <input id="db-size" class="view" type="number" value="5" min="1" max="40"></label>
      <label title="eq. 2: cost of a brushed pixel that keeps the base; large keeps the whole stroke">ν <input id="db-nu" class="view" type="number" value="1000" min="0" step="any"></label>
      <label><input id="db-labels" class="view" type="checkbox" checked> labelling and seam</label>
      <button id="db-undo" type="button" disabled>Undo</button>
      <button id="db-clear" type="button">Clear stroke</button>
      <button id="db-keep" type="button">Add to gallery</button>`,
    sideHtml: `<figure><canvas id="db-reference" class="paintable" aria-label="Reference texture: paint here"></canvas>
      <figcaption>reference: paint over the elements to move</figcaption></figure>
      <p class="legend">On the base: blue, the region the graph cut took from the reference (bright where
      brushed); red, the seam. Brush plain background over elements to remove them.</p>`,
    mount() {
      const ref = referenceCanvas();
      ref.onpointerdown = (e) => { painting = true; paintAt(e); };
      ref.onpointermove = (e) => painting && paintAt(e);
      this.onPointerUp = () => { painting = false; };
      window.addEventListener('pointerup', this.onPointerUp);
      paintable(ref, 'Brush the reference over the elements to move');
      ui.outputCanvas.onclick = placeAt;
      paintable(ui.outputCanvas, 'Place the brushed elements on the base (Enter)');
      ui.$('db-undo').addEventListener('click', () => {
        brush?.undo();
        document.body.dataset.strokes = String(brush?.undoDepth ?? 0);
        readout('undone');
        drawBase();
      });
      ui.$('db-clear').addEventListener('click', () => { mask?.fill(0); drawReference(); });
      ui.$('db-labels').addEventListener('change', drawBase);
      // A new nu applies to the strokes to come: the strokes made and their undo stay.
      ui.$('db-nu').addEventListener('change', () => {
        try {
          brush?.setNu(Number(ui.$('db-nu').value));
          readout(`ν ${ui.$('db-nu').value} for the next strokes`);
        } catch (error) {
          readout(error.message);
        }
      });
      ui.$('db-keep').addEventListener('click', () => {
        if (!brush) return;
        const index = gallery.add(`${gallery.baseItem.label} · brushed`, brush.toExemplar());
        readout(`added as texture ${index + 1}; make it the base to keep brushing it`);
      });
      this.reset();
    },
    unmount() {
      ui.outputCanvas.onclick = null;
      unpaintable(ui.outputCanvas);
      window.removeEventListener('pointerup', this.onPointerUp);
      brush?.free();
      brush = null;
    },
    onSelection() {
      drawReference();
      drawBase();
    },
    reset() {
      if (!gallery.baseItem) return;
      if (gallery.reference === gallery.base && gallery.items.length > 1) gallery.select('reference', gallery.items.length - 1);
      drawReference();
      drawBase();
    },
  };
}
