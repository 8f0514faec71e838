// The demo page: loads the wasm package, wires the exemplar input and the shared controls, and
// hosts one panel per method (www/panels/). A panel gives its options, its side view, and
// step / onStep / reset; the page paces it with Run / Pause / Step / Reset.
import init, { version } from './pkg/texsynth.js';
import { drawInto } from './lib/canvas.js';
import { setupInput } from './lib/input.js';
import { Runner } from './lib/runner.js';
import * as design from './panels/design.js';
import * as features from './panels/features.js';
import * as flow from './panels/flow.js';
import * as graphcut from './panels/graphcut.js';
import * as merge from './panels/merge.js';
import * as optimization from './panels/optimization.js';
import * as video from './panels/video.js';

const PANELS = [optimization, graphcut, merge, flow, design, features, video];
const $ = (id) => document.getElementById(id);

function showError(message) {
  $('error').textContent = message;
  $('error').hidden = false;
}

function clearError() {
  $('error').hidden = true;
  $('error').textContent = '';
}

const state = { exemplar: null, panel: null, runner: null };

const clampInt = (value, lo, hi, fallback) => {
  const n = Math.round(Number(value));
  return Number.isFinite(n) ? Math.min(hi, Math.max(lo, n)) : fallback;
};

const ui = {
  $,
  outputCanvas: null,
  exemplar: () => state.exemplar,
  outputWidth: () => clampInt($('out-width').value, 16, 2048, 256),
  outputHeight: () => clampInt($('out-height').value, 16, 2048, 256),
  seed: () => clampInt($('seed').value, 0, 2 ** 32, 1),
  /** Runs the current session on (a panel calls it when new input should be followed). */
  run: () => {
    if (!state.exemplar || !state.runner) return;
    state.runner.run();
    setStatus('running…');
  },
};

function setStatus(text) {
  $('status').textContent = text;
}

function resetPanel() {
  state.runner?.pause();
  state.panel?.reset();
  setStatus(state.exemplar ? 'ready' : 'pick an exemplar');
}

function selectPanel(module) {
  resetPanel();
  state.panel?.unmount?.();
  state.panel = module.createPanel(ui);
  $('method-options').innerHTML = state.panel.optionsHtml;
  $('side').innerHTML = state.panel.sideHtml;
  for (const button of $('methods').children) {
    button.setAttribute('aria-selected', String(button.dataset.panel === module.id));
  }
  state.panel.mount();
  for (const input of $('method-options').querySelectorAll('input, select')) {
    if (!input.classList.contains('view')) input.addEventListener('change', resetPanel);
  }
  state.runner = new Runner({
    step: () => state.panel.step(),
    onStep: (event) => {
      clearError();
      state.panel.onStep(event);
      setStatus(event.done ? 'done' : state.runner.running ? 'running…' : 'paused');
    },
    onDone: () => setStatus('done'),
    onError: (message) => {
      showError(message);
      setStatus('stopped');
    },
  });
  resetPanel();
}

function setExemplar(exemplar, label) {
  clearError();
  state.runner?.pause();
  state.exemplar?.free();
  state.exemplar = exemplar;
  // After the swap, so that a panel that keeps a copy of the exemplar sees the new one.
  resetPanel();
  drawInto($('exemplar-canvas'), exemplar);
  const kind = { 1: 'grey', 2: 'grey + alpha', 3: 'RGB', 4: 'RGBA' }[exemplar.channels];
  $('exemplar-info').textContent = `${label}: ${exemplar.width}×${exemplar.height}, ${kind}`;
  document.body.dataset.exemplar = label;
  document.body.dataset.exemplarSize = `${exemplar.width}x${exemplar.height}`;
  setStatus('ready');
}

async function main() {
  await init();
  $('version').textContent = `v${version()}`;
  ui.outputCanvas = $('output-canvas');
  for (const module of PANELS) {
    const button = document.createElement('button');
    button.type = 'button';
    button.role = 'tab';
    button.dataset.panel = module.id;
    button.textContent = module.title;
    button.addEventListener('click', () => selectPanel(module));
    $('methods').append(button);
  }
  selectPanel(PANELS[0]);
  $('run').addEventListener('click', () => {
    if (!state.exemplar) return;
    state.runner.run();
    setStatus('running…');
  });
  $('pause').addEventListener('click', () => {
    state.runner.pause();
    setStatus('paused');
  });
  $('step').addEventListener('click', () => state.exemplar && state.runner.stepOnce());
  $('reset').addEventListener('click', resetPanel);
  for (const id of ['seed', 'out-width', 'out-height']) $(id).addEventListener('change', resetPanel);

  const input = setupInput({
    samplesEl: $('samples'),
    uploadEl: $('upload'),
    dropEl: $('drop'),
    workingSizeEl: $('working-size'),
    dialogEl: $('large-upload'),
    onExemplar: setExemplar,
    onError: showError,
  });
  await input.loadSample('tiles_128');
  document.body.dataset.ready = 'true';
}

main().catch((error) => showError(`could not start: ${error.message ?? error}`));
