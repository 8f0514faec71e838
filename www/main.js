// The demo page: loads the wasm package, wires the exemplar input, and hosts one panel per method.
import init, { version } from './pkg/texsynth.js';
import { drawInto } from './lib/canvas.js';
import { setupInput } from './lib/input.js';

const $ = (id) => document.getElementById(id);

function showError(message) {
  const box = $('error');
  box.textContent = message;
  box.hidden = false;
}

function clearError() {
  $('error').hidden = true;
  $('error').textContent = '';
}

const state = { exemplar: null, label: '' };

function setExemplar(exemplar, label) {
  clearError();
  state.exemplar?.free();
  state.exemplar = exemplar;
  state.label = label;
  drawInto($('exemplar-canvas'), exemplar);
  const kind = { 1: 'grey', 2: 'grey + alpha', 3: 'RGB', 4: 'RGBA' }[exemplar.channels];
  $('exemplar-info').textContent = `${label}: ${exemplar.width}×${exemplar.height}, ${kind}`;
  document.body.dataset.exemplar = label;
}

async function main() {
  await init();
  $('version').textContent = `v${version()}`;
  // Method panels register here as they land; until then the controls have nothing to drive.
  for (const id of ['run', 'pause', 'step', 'reset']) $(id).disabled = true;
  $('status').textContent = 'no synthesis method loaded yet';
  $('side').innerHTML = '<p class="empty">Plots and teaching views appear here while a method runs.</p>';

  const input = setupInput({
    samplesEl: $('samples'),
    uploadEl: $('upload'),
    dropEl: $('drop'),
    onExemplar: setExemplar,
    onError: showError,
  });
  await input.loadSample('tiles_128');
  document.body.dataset.ready = 'true';
}

main().catch((error) => showError(`could not start: ${error.message ?? error}`));
