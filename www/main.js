// The demo page: loads the wasm package, wires the exemplar input and the shared controls, and
// hosts one panel per method (www/panels/). A panel gives its options, its side view, and
// step / onStep / reset; the page paces it with Run / Pause / Step / Reset. Around every panel the
// page keeps the step history (lib/history-view.js), the URL state (lib/url-state.js) and the
// keyboard behaviour of the method tabs (lib/tablist.js). A panel that draws on canvases of its
// own (Compare) gives `stageHtml`, `hidesOutput` and `viewCanvases()` for the history to capture.
import init, { version } from './pkg/texsynth.js';
import { drawInto } from './lib/canvas.js';
import { createHistoryView } from './lib/history-view.js';
import { setupInput } from './lib/input.js';
import { plotLength } from './lib/plot.js';
import { Runner } from './lib/runner.js';
import { pageWorker } from './lib/worker.js';
import { SAMPLES } from './lib/samples.js';
import { installKeyboardBrush } from './lib/keyboard-brush.js';
import { setupTablist } from './lib/tablist.js';
import { readOptions, readUrlState, urlQuery, writeOptions } from './lib/url-state.js';
import * as compare from './panels/compare.js';
import * as design from './panels/design.js';
import * as features from './panels/features.js';
import * as flow from './panels/flow.js';
import * as graphcut from './panels/graphcut.js';
import * as inpainting from './panels/inpainting.js';
import * as merge from './panels/merge.js';
import * as optimization from './panels/optimization.js';
import * as video from './panels/video.js';

const PANELS = [optimization, graphcut, merge, flow, design, features, video, inpainting, compare];
const $ = (id) => document.getElementById(id);

function showError(message) {
  $('error').textContent = message;
  $('error').hidden = false;
}

function clearError() {
  $('error').hidden = true;
  $('error').textContent = '';
}

// `sampleId` names the built-in sample shown (null for an upload); `loaded` turns the URL
// updates on once the URL's own state has been restored.
// `resets` counts resets, so a drawing that finishes after one is not put in the new history.
const state = { exemplar: null, sampleId: null, panel: null, panelId: null, runner: null, history: null, loaded: false, resets: 0 };
let syncTabs = () => {};

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
  /** Shows `message` in the page's error display (cleared by the next step that succeeds). */
  showError: (message) => showError(message),
  /** Runs the current session on (a panel calls it when new input should be followed). */
  run: () => {
    if (!state.exemplar || !state.runner) return;
    state.history.goLive();
    state.runner.run();
    setStatus('running…');
  },
};

function setStatus(text) {
  $('status').textContent = text;
}

function resetPanel() {
  state.resets += 1;
  state.runner?.pause();
  state.history?.clear();
  state.panel?.reset();
  setStatus(state.exemplar ? 'ready' : 'pick an exemplar');
}

/** Greys the toolbar's output size and seed where the panel decides them itself, with the
 * panel's reason as their tooltip (a field that stays live and does nothing misleads). */
function syncToolbar(panel) {
  const owned = [
    [['out-width', 'out-height'], panel.ownsOutputSize],
    [['seed'], panel.ownsSeed],
  ];
  for (const [ids, reason] of owned) {
    for (const id of ids) {
      $(id).disabled = Boolean(reason);
      if (reason) $(id).title = reason;
      else $(id).removeAttribute('title');
    }
  }
}

function selectPanel(module) {
  resetPanel();
  state.panel?.unmount?.();
  state.panel = module.createPanel(ui);
  state.panelId = module.id;
  $('method-options').innerHTML = state.panel.optionsHtml;
  $('side').innerHTML = state.panel.sideHtml;
  $('panel-stage').innerHTML = state.panel.stageHtml ?? '';
  $('output-wrap').hidden = Boolean(state.panel.hidesOutput);
  for (const button of $('methods').children) {
    button.setAttribute('aria-selected', String(button.dataset.panel === module.id));
  }
  $('method-options').setAttribute('aria-labelledby', `tab-${module.id}`);
  syncTabs();
  syncToolbar(state.panel);
  state.panel.mount();
  for (const input of $('method-options').querySelectorAll('input, select')) {
    if (!input.classList.contains('view')) input.addEventListener('change', resetPanel);
  }
  state.runner = new Runner({
    step: () => state.panel.step(),
    onStep: (event) => {
      clearError();
      const drawn = state.panel.onStep(event);
      // A panel that draws after fetching from the worker (video) returns that promise: the
      // history copies the canvas once it is drawn, unless a reset came in between.
      if (typeof drawn?.then === 'function') {
        const resets = state.resets;
        drawn.then(() => resets === state.resets && state.history.capture(event), () => {});
      } else {
        state.history.capture(event);
      }
      setStatus(event.done ? 'done' : state.runner.running ? 'running…' : 'paused');
    },
    onDone: () => setStatus('done'),
    onIdle: (why) => setStatus(why),
    onError: (message) => {
      showError(message);
      setStatus('stopped');
    },
  });
  resetPanel();
}

function setExemplar(exemplar, label, sampleId = null) {
  clearError();
  state.sampleId = sampleId;
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
  syncUrl();
}

/** Writes the page's state into its URL (without a new history entry: each edit is not a page). */
function syncUrl() {
  if (!state.loaded) return;
  const query = urlQuery({
    sample: state.sampleId ?? undefined,
    method: state.panelId,
    seed: $('seed').value,
    width: $('out-width').value,
    height: $('out-height').value,
    options: readOptions($('method-options')),
  });
  if (query !== location.search) {
    window.history.replaceState(null, '', query + location.hash);
    $('share-status').textContent = ''; // "link copied" was about the previous link
  }
  $('share-link').value = location.href;
}

async function copyLink() {
  syncUrl();
  const url = location.href;
  const upload = state.sampleId ? '' : ' (without the exemplar: it is an upload, so the link opens the default sample)';
  try {
    await navigator.clipboard.writeText(url);
    $('share-status').textContent = `link copied${upload}`;
  } catch {
    // No clipboard (an insecure origin, or permission refused): the link, selected, to copy by hand.
    $('share-link-label').hidden = false;
    $('share-link').value = url;
    $('share-link').focus();
    $('share-link').select();
    $('share-status').textContent = `copy the selected link${upload}`;
  }
}

function setupHistory() {
  state.history = createHistoryView({
    range: $('history-range'),
    live: $('history-live'),
    info: $('history-info'),
    strip: $('history-strip'),
    canvases: () => state.panel?.viewCanvases?.() ?? [ui.outputCanvas],
    plots: () => [...document.querySelectorAll('#side canvas, #panel-stage canvas')].filter((c) => plotLength(c) > 0),
    // Looking back pauses a running session, so the view stays where the user put it.
    onScrub: () => {
      if (!state.runner?.running) return;
      state.runner.pause();
      setStatus('paused (viewing the history)');
    },
  });
}

async function main() {
  await init();
  $('version').textContent = `v${version()}`;
  // The page's worker runs the threaded module where the page is cross-origin isolated: say which.
  pageWorker().ready.then(
    (info) => {
      const threads = info.threaded ? `${info.threads} thread${info.threads === 1 ? '' : 's'}` : 'single-threaded';
      $('version').textContent = `v${version()} · ${threads}`;
      $('version').dataset.threads = String(info.threads);
      $('version').title = info.threaded
        ? 'Each synthesis runs on a pool of threads over shared memory (the threaded module).'
        : `Each synthesis runs on one core: ${info.reason}`;
    },
    () => {},
  );
  ui.outputCanvas = $('output-canvas');
  setupHistory();
  const wanted = readUrlState(location.search);
  if (wanted.seed !== undefined) $('seed').value = wanted.seed;
  if (wanted.width !== undefined) $('out-width').value = wanted.width;
  if (wanted.height !== undefined) $('out-height').value = wanted.height;
  for (const module of PANELS) {
    const button = document.createElement('button');
    button.type = 'button';
    button.role = 'tab';
    button.id = `tab-${module.id}`;
    button.setAttribute('aria-controls', 'method-options');
    button.dataset.panel = module.id;
    button.textContent = module.title;
    button.addEventListener('click', () => selectPanel(module));
    $('methods').append(button);
  }
  syncTabs = setupTablist($('methods'));
  installKeyboardBrush(document);
  selectPanel(PANELS.find((p) => p.id === wanted.method) ?? PANELS[0]);
  writeOptions($('method-options'), wanted.options);
  $('run').addEventListener('click', () => {
    if (!state.exemplar) return;
    state.history.goLive();
    state.runner.run();
    setStatus('running…');
  });
  $('pause').addEventListener('click', () => {
    state.runner.pause();
    setStatus('paused');
  });
  $('step').addEventListener('click', () => {
    if (!state.exemplar) return;
    state.history.goLive();
    state.runner.stepOnce();
  });
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
  // A link naming no sample, or one this build does not have, opens the default.
  await input.loadSample(SAMPLES.some((s) => s.id === wanted.sample) ? wanted.sample : 'tiles_128');
  state.loaded = true;
  syncUrl();
  // Any edit, tab or sample choice: the URL follows once the page's own handlers have run,
  // coalesced (dragging a slider would otherwise call replaceState faster than browsers allow).
  let pendingSync = null;
  for (const type of ['input', 'change', 'click']) {
    document.addEventListener(type, () => {
      clearTimeout(pendingSync);
      pendingSync = setTimeout(syncUrl, 100);
    });
  }
  $('copy-link').addEventListener('click', copyLink);
  // A view toggled while an earlier step is shown (say, the teaching view): back to the live
  // canvases first (capture phase: before the panel's own handler redraws over them).
  $('method-options').addEventListener('change', () => state.history.goLive(), true);
  document.querySelector('.skip').addEventListener('click', (event) => {
    event.preventDefault();
    $('methods').querySelector('[aria-selected="true"]').focus();
  });
  document.body.dataset.ready = 'true';
}

main().catch((error) => showError(`could not start: ${error.message ?? error}`));
