// The exemplar input: built-in samples, file upload and drag-and-drop. Everything is decoded by
// wasm (`Exemplar.fromBytes`), so a file the library cannot read shows the library's own message.
// An upload above the working size goes through the large-upload prompt first.
import { Exemplar } from '../pkg/texsynth.js';
import { setupLargeUpload } from './large-upload.js';
import { SAMPLES } from './samples.js';
import { rovingFocus, syncRoving } from './tablist.js';

/**
 * Wires the input panel. `onExemplar(exemplar, label, sampleId)` is called with each new exemplar
 * (sampleId: the built-in sample's id, null for an upload);
 * `onError(message)` with the message of anything that failed to load.
 */
export function setupInput({ samplesEl, uploadEl, dropEl, workingSizeEl, dialogEl, onExemplar, onError }) {
  const large = setupLargeUpload({ dialogEl, workingSizeEl });
  const buttons = new Map();
  for (const sample of SAMPLES) {
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'sample';
    button.setAttribute('role', 'listitem');
    button.dataset.sample = sample.id;
    button.title = sample.label;
    button.setAttribute('aria-label', sample.label);
    button.setAttribute('aria-pressed', 'false');
    const img = document.createElement('img');
    img.src = sample.url;
    img.alt = '';
    button.append(img);
    button.addEventListener('click', () => loadSample(sample));
    samplesEl.append(button);
    buttons.set(sample.id, button);
  }

  // The 32 samples are one Tab stop; the arrow keys move in the grid.
  rovingFocus(samplesEl, 'button', { grid: true });
  syncRoving(samplesEl, 'button', () => false);

  function select(id) {
    for (const [key, button] of buttons) button.setAttribute('aria-pressed', String(key === id));
    if (id !== null) syncRoving(samplesEl, 'button', (b) => b.dataset.sample === id);
  }

  async function loadBytes(bytes, label, id = null) {
    try {
      const exemplar = Exemplar.fromBytes(bytes);
      // The samples are 64 and 128 pixels: only uploads are checked against the working size.
      const chosen = id === null ? await large.check(exemplar, label) : { exemplar, label };
      if (!chosen) return; // cancelled: the previous exemplar stays
      select(id);
      onExemplar(chosen.exemplar, chosen.label, id);
    } catch (error) {
      onError(`${label}: ${error.message ?? error}`);
    }
  }

  async function loadSample(sample) {
    try {
      const response = await fetch(sample.url);
      if (!response.ok) throw new Error(`HTTP ${response.status}`);
      await loadBytes(new Uint8Array(await response.arrayBuffer()), sample.label, sample.id);
    } catch (error) {
      onError(`${sample.label}: ${error.message ?? error}`);
    }
  }

  async function loadFile(file) {
    if (!file) return;
    await loadBytes(new Uint8Array(await file.arrayBuffer()), file.name);
  }

  uploadEl.addEventListener('change', () => loadFile(uploadEl.files[0]));
  dropEl.addEventListener('dragover', (event) => {
    event.preventDefault();
    dropEl.classList.add('over');
  });
  dropEl.addEventListener('dragleave', () => dropEl.classList.remove('over'));
  dropEl.addEventListener('drop', (event) => {
    event.preventDefault();
    dropEl.classList.remove('over');
    loadFile(event.dataTransfer.files[0]);
  });

  return { loadSample: (id) => loadSample(SAMPLES.find((s) => s.id === id) ?? SAMPLES[0]) };
}
