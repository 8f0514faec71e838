// The "Compare" panel: one exemplar, one seed and one output size run through two or more
// methods, side by side, each with the method-independent quality metrics (lib/quality.js) and
// its wall time. Texture optimization against graph cut against feature-guided synthesis, or the
// plain texture energy against the wavelet energies of Shen et al. 2009 (eq. 4). Every method
// uses the library's defaults (the same the method's own panel starts from). The
// sessions run in the page's worker and are stepped in turn by the page's Runner, one step of one
// method per step, so all of them are seen growing together.
import { drawInto } from '../lib/canvas.js';
import { showQualityOrWhy } from '../lib/quality.js';
import { pageWorker, remoteSession } from '../lib/worker.js';

export const id = 'compare';
export const title = 'Compare';

const METHODS = [
  { key: 'optimization', name: 'Texture optimization', note: 'plain energy, Kwatra et al. 2005', kind: 'TextureOptimization', extra: { energy: 'pixels' } },
  { key: 'graphcut', name: 'Graph cut', note: 'Kwatra et al. 2003', kind: 'GraphcutTextures', extra: {} },
  { key: 'features', name: 'Feature-guided', note: 'Wu & Yu 2004', kind: 'FeatureSynthesis', extra: {} },
  { key: 'haar', name: 'Haar energy', note: 'Haar wavelets, Shen et al. 2009', kind: 'TextureOptimization', extra: { energy: 'haar' } },
  { key: 'daubechies', name: 'Daubechies energy', note: 'Daubechies D4, Shen et al. 2009', kind: 'TextureOptimization', extra: { energy: 'daubechies' } },
];

const PRESETS = {
  methods: ['optimization', 'graphcut', 'features'],
  energies: ['optimization', 'haar', 'daubechies'],
};

const OPTIONS_HTML = `
  <fieldset class="compare-pick">
    <legend>Run side by side</legend>
    ${METHODS.map((m) => `<label title="${m.note}"><input type="checkbox" id="cmp-${m.key}"${PRESETS.methods.includes(m.key) ? ' checked' : ''}> ${m.name}</label>`).join('\n    ')}
  </fieldset>
  <span class="compare-presets">
    <button type="button" id="cmp-preset-methods" class="view">Methods: optimization · graph cut · feature-guided</button>
    <button type="button" id="cmp-preset-energies" class="view">Energies: plain · Haar · Daubechies</button>
  </span>`;

const SIDE_HTML = `
  <div class="readout" id="cmp-readout">pick two or more and press Run</div>
  <table class="compare-table" id="cmp-table" hidden>
    <caption>Side by side (lower is better, flat nearest the exemplar's 10%; best in bold)</caption>
    <thead><tr><th scope="col">method</th><th scope="col"><abbr title="coherence">coher.</abbr></th>
      <th scope="col"><abbr title="completeness">compl.</abbr></th><th scope="col"><abbr title="histogram">hist.</abbr></th>
      <th scope="col"><abbr title="flat fraction: the share of pixels flatter than the exemplar's flattest tenth (the exemplar itself: about 10%; far above it, the output has washed out)">flat</abbr></th>
      <th scope="col">time</th></tr></thead>
    <tbody></tbody>
  </table>
  <p class="legend">Each method runs on the same exemplar, seed and output size, with its defaults. The methods
  take turns: one step of each in the page's worker. Time is the wall time of that method's own steps (making the
  session included), so it does not count the others' turns. Quality: lower is better for every figure but flat,
  which is best near the exemplar's own 10% (far above it, the output has washed out).</p>`;

export function createPanel(ui) {
  let runs = [];
  let turn = 0;
  let generation = 0;

  const figureHtml = (m) => `
    <figure class="compare-item" id="cmp-item-${m.key}">
      <figcaption><strong>${m.name}</strong> <small>${m.note}</small></figcaption>
      <canvas id="cmp-canvas-${m.key}" width="${ui.outputWidth()}" height="${ui.outputHeight()}" aria-label="${m.name} output"></canvas>
      <p class="compare-time" id="cmp-time-${m.key}">waiting</p>
      <p class="quality" id="cmp-quality-${m.key}"></p>
    </figure>`;

  function drop() {
    generation++;
    for (const run of runs) run.session?.free();
    runs = [];
    turn = 0;
  }

  function build() {
    drop();
    const chosen = METHODS.filter((m) => ui.$(`cmp-${m.key}`)?.checked);
    const grid = ui.$('cmp-grid');
    if (!grid) return;
    grid.innerHTML = chosen.map(figureHtml).join('');
    runs = chosen.map((method) => ({
      method, session: null, time: 0, steps: 0, done: false, error: null,
      canvas: ui.$(`cmp-canvas-${method.key}`),
    }));
    ui.$('cmp-readout').textContent = runs.length < 2 ? 'pick two or more to compare' : `${runs.length} methods: press Run or Step`;
    table();
    delete document.body.dataset.compareDone;
  }

  const options = (method) => ({ outputWidth: ui.outputWidth(), outputHeight: ui.outputHeight(), seed: ui.seed(), ...method.extra });

  /** The figures of every finished method in one table, the best of each column in bold. */
  function table() {
    const done = runs.filter((r) => r.done && !r.error && r.figures);
    ui.$('cmp-table').hidden = done.length === 0;
    const columns = ['coherence', 'completeness', 'histogram', 'flat', 'time'];
    // The flat fraction is best nearest the exemplar's own (about 10% by its definition): below
    // it an output is busier than the exemplar, above it washed out. Every other figure: lowest.
    const FLAT_EXEMPLAR = 0.1;
    const badness = (c, v) => (c === 'flat' ? Math.abs(v - FLAT_EXEMPLAR) : v);
    const best = Object.fromEntries(columns.map((c) => [c, Math.min(...done.map((r) => badness(c, r.figures[c])))]));
    ui.$('cmp-table').tBodies[0].replaceChildren(...done.map((run) => {
      const row = document.createElement('tr');
      const name = document.createElement('th');
      name.scope = 'row';
      name.textContent = run.method.name;
      row.append(name, ...columns.map((c) => {
        const cell = document.createElement('td');
        const value = run.figures[c];
        cell.textContent = c === 'time' ? `${(value / 1000).toFixed(2)} s`
          : c === 'flat' ? `${(value * 100).toFixed(1)}%` : value.toExponential(1);
        if (done.length > 1 && badness(c, value) === best[c]) cell.className = 'best';
        return cell;
      }));
      return row;
    }));
  }

  function timeText(run) {
    if (run.error) return `failed: ${run.error}`;
    const state = run.done ? 'done' : 'running';
    return `${state} · ${run.steps} steps · ${(run.time / 1000).toFixed(2)} s`;
  }

  return {
    id,
    title,
    optionsHtml: OPTIONS_HTML,
    sideHtml: SIDE_HTML,
    stageHtml: '<div class="compare-grid" id="cmp-grid"></div>',
    hidesOutput: true,
    viewCanvases: () => runs.map((r) => r.canvas),
    mount() {
      for (const [preset, keys] of Object.entries(PRESETS)) {
        ui.$(`cmp-preset-${preset}`).addEventListener('click', () => {
          for (const m of METHODS) ui.$(`cmp-${m.key}`).checked = keys.includes(m.key);
          // As if the user had ticked them: the page resets the run (and updates the URL).
          ui.$(`cmp-${METHODS[0].key}`).dispatchEvent(new Event('change', { bubbles: true }));
        });
      }
    },
    unmount() {
      drop();
    },
    async step() {
      const mine = generation;
      const active = runs.filter((r) => !r.done);
      if (runs.length < 2 || active.length === 0) return null;
      const run = active[turn++ % active.length];
      // The worker's start (loading the wasm) is no method's time.
      await pageWorker().ready;
      if (mine !== generation) return null;
      const start = performance.now();
      let event;
      try {
        if (!run.session) {
          const made = await remoteSession(run.method.kind, [ui.exemplar(), options(run.method)], { views: ['renderInto'] });
          if (mine !== generation) {
            made.free();
            return null;
          }
          run.session = made;
        }
        event = await run.session.step();
      } catch (error) {
        // One method refusing (say, an exemplar too small for its patches) leaves the others running.
        if (mine !== generation) return null;
        run.error = error.message ?? String(error);
        run.done = true;
        return { method: run.method.key, failed: true, done: runs.every((r) => r.done) };
      }
      if (mine !== generation) return null;
      run.time += performance.now() - start;
      run.steps += 1;
      run.done = Boolean(event.done);
      // No `level` here: the history's level strip is per method, and these steps interleave.
      return { method: run.method.key, methodDone: run.done, done: runs.every((r) => r.done) };
    },
    onStep(event) {
      const run = runs.find((r) => r.method.key === event.method);
      if (!run) return;
      if (run.session) drawInto(run.canvas, run.session);
      ui.$(`cmp-time-${run.method.key}`).textContent = timeText(run);
      ui.$('cmp-readout').textContent = runs.map((r) => `${r.method.name}: ${r.error ? 'failed' : r.done ? 'done' : `${r.steps} steps`}`).join(' · ');
      if (event.methodDone) {
        const element = ui.$(`cmp-quality-${run.method.key}`);
        const mine = generation;
        run.quality = showQualityOrWhy(element, ui.exemplar(), run.session, () => mine === generation).then((shown) => {
          if (mine !== generation || !shown) return;
          const figure = (name) => Number(element.dataset[name]);
          run.figures = {
            coherence: figure('coherence'), completeness: figure('completeness'), histogram: figure('histogram'), flat: figure('flat'), time: run.time,
          };
          table();
        });
      }
      if (event.done) {
        const mine = generation;
        Promise.allSettled(runs.map((r) => r.quality)).then(() => {
          if (mine === generation) document.body.dataset.compareDone = 'true';
        });
      }
    },
    reset() {
      build();
    },
  };
}
