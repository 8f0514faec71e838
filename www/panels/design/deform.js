// Stage 1 (Shen et al. 2009, section 3.1): global deformations of the base texture. Every value
// of each range gives one deformed texture I_g, added to the gallery.
import { deformationSet } from '../../pkg/texsynth.js';
import { drawInto } from '../../lib/canvas.js';

export const id = 'deform';
export const title = 'Deform';

const range = (name, label, from, to, step, on) => `
  <span class="range" title="${label}: from, to, step">
    <label><input id="dd-${name}-on" type="checkbox" class="view" ${on ? 'checked' : ''}> ${label}</label>
    <input id="dd-${name}-from" class="view" type="number" value="${from}" step="any" aria-label="${label}: from">
    <input id="dd-${name}-to" class="view" type="number" value="${to}" step="any" aria-label="${label}: to">
    <input id="dd-${name}-step" class="view" type="number" value="${step}" step="any" aria-label="${label}: step">
  </span>`;

export function createStage({ ui, gallery, readout }) {
  const read = (name) => (ui.$(`dd-${name}-on`).checked
    ? ['from', 'to', 'step'].reduce((o, k) => ({ ...o, [k]: Number(ui.$(`dd-${name}-${k}`).value) }), {})
    : undefined);

  function showBase() {
    const item = gallery.baseItem;
    if (item) drawInto(ui.outputCanvas, item.exemplar);
  }

  function makeSet() {
    const item = gallery.baseItem;
    if (!item) return;
    const ranges = {
      rotation: read('rotation'),
      scale: read('scale'),
      shift: read('shift'),
      mirror: ui.$('dd-mirror').checked,
      flip: ui.$('dd-flip').checked,
    };
    const start = performance.now();
    const set = deformationSet(item.exemplar, ranges);
    for (const { label, exemplar } of set) gallery.add(`${item.label} · ${label}`, exemplar);
    readout(`${set.length} deformed textures in ${(performance.now() - start).toFixed(0)} ms (rotations and scales keep only pixels from inside the texture)`);
    document.body.dataset.deformed = String(set.length);
  }

  return {
    hint: 'choose ranges, then "Make deformed set"; the gallery collects the textures',
    optionsHtml: `
      ${range('rotation', 'rotate °', 0, 90, 30, true)}
      ${range('scale', 'scale', 0.75, 1.5, 0.75, true)}
      ${range('shift', 'shift ×size', 0.5, 0.5, 0.25, false)}
      <label><input id="dd-mirror" class="view" type="checkbox" checked> mirror</label>
      <label><input id="dd-flip" class="view" type="checkbox"> flip</label>
      <button id="dd-make" type="button">Make deformed set</button>`,
    mount() {
      ui.$('dd-make').addEventListener('click', () => {
        try {
          makeSet();
        } catch (error) {
          readout(error.message);
        }
      });
      showBase();
    },
    onSelection: showBase,
    reset: showBase,
  };
}
